#include "hexadapt/io/exodus.h"

#include <exodusII.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/mesh/structured.h"
#include "io/io_test_util.h"

namespace hexadapt::io {
namespace {

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Two materials on a grid, the material index alternating by column, with fractions.
MeshData two_materials(MeshData d, int nx) {
  DataArray material{"material", 1, ScalarType::int32, {}};
  DataArray vf_steel{"vf_steel", 1, ScalarType::float64, {}};
  DataArray vf_air{"vf_air", 1, ScalarType::float64, {}};
  for (index_t c = 0; c < d.n_cells(); ++c) {
    const int m = (c % nx) < nx / 2 ? 0 : 1;
    material.values.push_back(m);
    vf_steel.values.push_back(m == 0 ? 0.75 : 0.125);
    vf_air.values.push_back(m == 0 ? 0.25 : 0.875);
  }
  d.set_cell_array(material);
  d.set_cell_array(vf_steel);
  d.set_cell_array(vf_air);
  DataArray target{"target", 3, ScalarType::float64, {}};
  for (const Vec3& p : d.points)
    for (int k = 0; k < 3; ++k) target.values.push_back(p[k] + 0.5);
  d.set_point_array(target);
  d.metadata = {{"hexadapt_tool", "hexadapt-test"}, {"hexadapt_materials", "steel,air"}};
  return d;
}

void expect_round_trip(const MeshData& d, const MeshData& r) {
  EXPECT_EQ(r.dim, d.dim);
  EXPECT_EQ(r.points, d.points);
  EXPECT_EQ(test::cell_ids(r), test::cell_ids(d));
  for (const char* name : {"material", "vf_steel", "vf_air"}) {
    ASSERT_NE(r.find_cell_array(name), nullptr) << name;
    EXPECT_EQ(r.find_cell_array(name)->values, d.find_cell_array(name)->values) << name;
  }
  ASSERT_NE(r.find_point_array("target"), nullptr);
  EXPECT_EQ(r.find_point_array("target")->values, d.find_point_array("target")->values);
  bool named = false;
  for (const auto& [k, v] : r.metadata)
    named = named || (k == "hexadapt_materials" && v == "steel,air");
  EXPECT_TRUE(named);
}

TEST(Exodus, QuadsRoundTripInCellOrder) {
  const MeshData d = two_materials(from_mesh(make_quad_grid(4, 3)), 4);
  const std::string path = test::temp_path("quads.exo");
  write_mesh(d, path);
  expect_round_trip(d, read_mesh(path));
  std::filesystem::remove(path);
}

TEST(Exodus, HexesRoundTripInCellOrder) {
  const MeshData d = two_materials(from_mesh(make_hex_grid(4, 2, 3)), 4);
  for (const char* ext : {".e", ".g"}) {
    const std::string path = test::temp_path(std::string("hexes") + ext);
    write_mesh(d, path);
    expect_round_trip(d, read_mesh(path));
    std::filesystem::remove(path);
  }
}

// Info records hold 80 characters a line: every entry comes back whole, whatever it holds.
TEST(Exodus, MetadataComesBackFromTheInfoRecords) {
  MeshData d = two_materials(from_mesh(make_quad_grid(2, 1)), 2);
  std::string record =
      "{\"fractions\": [\"Volume Fraction for Body, Nose\"], \"note\": \"a\\\\b\nc\"}";
  while (record.size() < 300) record += " pad";
  d.metadata = {{"hexadapt_tool", "hexadapt-test"},
                {"hexadapt_input", record},
                {"key: with colon", "+plus"},
                {"+lead", ""},
                {"hexadapt_command", std::string(80, 'x')},
                {"hexadapt_materials", join_material_names({"steel", "Body, Nose"})}};
  const std::string path = test::temp_path("info.exo");
  write_mesh(d, path);
  const MeshData r = read_mesh(path);
  std::filesystem::remove(path);
  EXPECT_EQ(r.metadata, d.metadata);
}

// Random entries of the characters the info records escape or lose (spaces ending a line).
TEST(Exodus, RandomMetadataComesBackWhole) {
  MeshData d = two_materials(from_mesh(make_quad_grid(2, 1)), 2);
  std::mt19937 rng(7);
  const std::string alphabet = "  \\:+\na,";
  auto text = [&](std::size_t max) {
    std::string t(std::uniform_int_distribution<std::size_t>(0, max)(rng), ' ');
    for (char& c : t) c = alphabet[rng() % alphabet.size()];
    return t;
  };
  d.metadata.clear();
  for (int k = 0; k < 60; ++k) d.metadata.emplace_back("k" + text(20), text(250));
  d.metadata.emplace_back("hexadapt_materials", "steel,air");
  const std::string path = test::temp_path("random_info.exo");
  write_mesh(d, path);
  const MeshData r = read_mesh(path);
  std::filesystem::remove(path);
  ASSERT_EQ(r.metadata.size(), d.metadata.size());
  for (std::size_t k = 0; k < d.metadata.size(); ++k)
    EXPECT_EQ(r.metadata[k], d.metadata[k]) << "entry " << k;
}

// A mesh without a `material` array is one block; read back, the block is the material.
TEST(Exodus, LongNamesAreKept) {
  MeshData d = two_materials(from_mesh(make_quad_grid(2, 1)), 2);
  const std::string name(60, 'n');
  d.metadata = {{"hexadapt_materials", "short," + name}};
  const std::string path = test::temp_path("long.exo");
  write_mesh(d, path);
  const MeshData r = read_mesh(path);
  std::string names;
  for (const auto& [k, v] : r.metadata)
    if (k == "hexadapt_materials") names = v;
  EXPECT_EQ(names, "short," + name);
  std::filesystem::remove(path);
}

TEST(Exodus, WithoutMaterialsOneBlock) {
  const MeshData d = from_mesh(make_quad_grid(2, 2));
  const std::string path = test::temp_path("plain.exo");
  write_mesh(d, path);
  const MeshData r = read_mesh(path);
  ASSERT_NE(r.find_cell_array("material"), nullptr);
  EXPECT_EQ(r.find_cell_array("material")->values, std::vector<double>(4, 0.0));
  std::filesystem::remove(path);
}

TEST(Exodus, SameMeshSameBytes) {
  const MeshData d = two_materials(from_mesh(make_hex_grid(3, 3, 2)), 3);
  const std::string a = test::temp_path("det_a.exo"), b = test::temp_path("det_b.exo");
  write_mesh(d, a);
  write_mesh(d, b);
  EXPECT_EQ(bytes_of(a), bytes_of(b));
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(Exodus, SetsOptionChangesTheFile) {
  const MeshData d = two_materials(from_mesh(make_quad_grid(4, 2)), 4);
  WriteOptions none;
  none.exodus_sets = ExodusSets::none;
  const std::string a = test::temp_path("sets_none.exo"), b = test::temp_path("sets_all.exo");
  write_mesh(d, a, none);
  write_mesh(d, b);
  EXPECT_LT(bytes_of(a).size(), bytes_of(b).size());
  expect_round_trip(d, read_mesh(a));
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(Exodus, ParsesSetChoices) {
  EXPECT_EQ(parse_exodus_sets("boundary"), ExodusSets::boundary);
  EXPECT_EQ(parse_exodus_sets("interfaces"), ExodusSets::interfaces);
  EXPECT_THROW(parse_exodus_sets("some"), OptionError);
}

TEST(Exodus, AFailedWriteLeavesTheOldFile) {
  const std::string path = test::temp_path("keep.exo");
  write_bytes(path, "old");
  MeshData bad = from_mesh(make_quad_grid(2, 1));
  bad.set_cell_array({"material", 1, ScalarType::int32, {0, -1}});
  EXPECT_THROW(write_mesh(bad, path), OptionError);
  EXPECT_EQ(bytes_of(path), "old");
  EXPECT_THROW(write_mesh(bad, "/dev/null.exo"), Error);
  std::filesystem::remove(path);
}

// A time series made with the Exodus API: fractions as element variables on 2 x 1 quads,
// the form Sculpt reads, at times 0, 0.5 and 1.
std::string time_series(const std::string& name, int stored_float_size = 8) {
  const std::string path = test::temp_path(name);
  int cpu = 8, io = stored_float_size;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  EXPECT_GE(id, 0);
  ex_put_init(id, "series", 2, 6, 2, 1, 0, 0);
  ex_put_block(id, EX_ELEM_BLOCK, 7, "QUAD", 2, 4, 0, 0, 0);
  const int conn[8] = {1, 2, 5, 4, 2, 3, 6, 5};
  ex_put_conn(id, EX_ELEM_BLOCK, 7, conn, nullptr, nullptr);
  const double x[6] = {0, 1, 2, 0, 1, 2}, y[6] = {0, 0, 0, 1, 1, 1};
  ex_put_coord(id, x, y, nullptr);
  ex_put_variable_param(id, EX_ELEM_BLOCK, 2);
  char a[] = "copper", b[] = "water";
  char* names[2] = {a, b};
  ex_put_variable_names(id, EX_ELEM_BLOCK, 2, names);
  for (int step = 1; step <= 3; ++step) {
    const double t = 0.5 * (step - 1);
    ex_put_time(id, step, &t);
    const double copper[2] = {t, 1 - t}, water[2] = {1 - t, t};
    ex_put_var(id, step, EX_ELEM_BLOCK, 1, 7, 2, copper);
    ex_put_var(id, step, EX_ELEM_BLOCK, 2, 7, 2, water);
  }
  ex_close(id);
  return path;
}

TEST(Exodus, ReadsTheChosenTimeStep) {
  const std::string path = time_series("series.exo");
  ReadOptions o;
  o.step = 2;
  const MeshData last = read_mesh(path, o);
  ASSERT_NE(last.find_cell_array("copper"), nullptr);
  EXPECT_EQ(last.find_cell_array("copper")->values, (std::vector<double>{1, 0}));
  o.step = 1;
  EXPECT_EQ(read_mesh(path, o).find_cell_array("water")->values, (std::vector<double>{0.5, 0.5}));
  o.step.reset();
  o.time = 0.0;
  EXPECT_EQ(read_mesh(path, o).find_cell_array("copper")->values, (std::vector<double>{0, 1}));
  const MeshData r = read_mesh(path, o);
  EXPECT_EQ(r.find_cell_array("material")->values, (std::vector<double>{0, 0}));
  bool named = false;
  for (const auto& [k, v] : r.metadata)
    named = named || (k == "hexadapt_materials" && v == "block_7");
  EXPECT_TRUE(named);
  o.time = 0.7;
  try {
    read_mesh(path, o);
    ADD_FAILURE() << "time 0.7 accepted";
  } catch (const InputError& e) {
    // The wording of every time series, .pvd too (VtkCollection.AnUnknownOrMissingStep...).
    const std::string expected =
        "no time step at t = 0.7; the series holds 3 steps: 0: t = 0, 1: t = 0.5, 2: t = 1";
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  o.time.reset();
  o.step = 3;
  EXPECT_THROW(read_mesh(path, o), InputError);
  EXPECT_THROW(read_mesh(path), InputError);  // several steps: one must be chosen
  std::filesystem::remove(path);
}

// A file storing its values as float32 (io word size 4) gives float32 arrays: the precision
// the fractions' default tolerances follow (fraction_tolerances.h).
TEST(Exodus, VariablesKeepTheStoredPrecision) {
  ReadOptions o;
  o.step = 1;
  for (int size : {4, 8}) {
    const std::string path = time_series("series" + std::to_string(size) + ".exo", size);
    const MeshData d = read_mesh(path, o);
    const DataArray* copper = d.find_cell_array("copper");
    ASSERT_NE(copper, nullptr);
    EXPECT_EQ(copper->type, size == 4 ? ScalarType::float32 : ScalarType::float64);
    EXPECT_EQ(copper->values, (std::vector<double>{0.5, 0.5}));
    std::filesystem::remove(path);
  }
}

TEST(Exodus, BadFilesAreInputErrors) {
  const MeshData d = two_materials(from_mesh(make_hex_grid(3, 2, 2)), 3);
  const std::string good = test::temp_path("good.exo");
  write_mesh(d, good);
  const std::string bytes = bytes_of(good);
  const std::string bad = test::temp_path("bad.exo");
  for (std::size_t keep : {std::size_t(0), std::size_t(3), std::size_t(40), bytes.size() / 4,
                           bytes.size() / 2, bytes.size() - 8}) {
    write_bytes(bad, bytes.substr(0, keep));
    EXPECT_THROW(read_mesh(bad), InputError) << "kept " << keep << " bytes";
  }
  write_bytes(bad, "CDF\x01 this is not netCDF at all");
  EXPECT_THROW(read_mesh(bad), InputError);
  write_bytes(bad, "# vtk DataFile Version 4.2\n");
  EXPECT_THROW(read_mesh(bad), InputError);
  EXPECT_THROW(read_mesh(test::temp_path("missing.exo")), IoError);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// Every cut of a valid file is refused (the netCDF library alone reads a cut tail as zeros).
TEST(Exodus, EveryTruncationIsAnInputError) {
  const MeshData d = two_materials(from_mesh(make_quad_grid(3, 2)), 3);
  const std::string good = test::temp_path("cut_good.exo"), bad = test::temp_path("cut.exo");
  write_mesh(d, good);
  const std::string bytes = bytes_of(good);
  for (std::size_t keep = 0; keep < bytes.size(); keep += 1 + bytes.size() / 97) {
    write_bytes(bad, bytes.substr(0, keep));
    EXPECT_THROW(read_mesh(bad), InputError) << "kept " << keep << " of " << bytes.size();
  }
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// The netCDF header's dimension `name` set to `value` (classic format: big-endian length
// after the padded name).
std::string with_dimension(std::string bytes, const std::string& name, std::uint32_t value) {
  std::string key(4, '\0');
  for (int k = 0; k < 4; ++k)
    key[static_cast<std::size_t>(k)] = static_cast<char>(name.size() >> (24 - 8 * k));
  key += name + std::string((4 - name.size() % 4) % 4, '\0');
  const std::size_t at = bytes.find(key);
  EXPECT_NE(at, std::string::npos) << name;
  for (int k = 0; k < 4; ++k)
    bytes[at + key.size() + static_cast<std::size_t>(k)] = static_cast<char>(value >> (24 - 8 * k));
  return bytes;
}

TEST(Exodus, LyingSizesAreInputErrors) {
  const MeshData d = two_materials(from_mesh(make_hex_grid(2, 2, 1)), 2);
  const std::string good = test::temp_path("lie_good.exo"), bad = test::temp_path("lie.exo");
  write_mesh(d, good);
  const std::string bytes = bytes_of(good);
  for (const auto& [name, value] :
       std::vector<std::pair<std::string, std::uint32_t>>{{"num_nodes", 0x7ffffff0u},
                                                          {"num_elem", 1u << 30},
                                                          {"num_el_in_blk1", 1u << 28},
                                                          {"num_dim", 1},
                                                          {"num_dim", 7},
                                                          {"num_nod_per_el1", 27},
                                                          {"num_elem", 1}}) {
    write_bytes(bad, with_dimension(bytes, name, value));
    EXPECT_THROW(read_mesh(bad), InputError) << name << " = " << value;
  }
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// A file made with the Exodus API: one block of `type` elements with `conn`, and `info` as
// its info records.
std::string one_block(const std::string& name, int dim, const char* type, int per_element,
                      const std::vector<int>& conn, std::vector<std::string> info = {}) {
  const std::string path = test::temp_path(name);
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  const int n_nodes = 8;
  const int n_elements = static_cast<int>(conn.size()) / per_element;
  ex_put_init(id, "one block", dim, n_nodes, n_elements, 1, 0, 0);
  ex_put_block(id, EX_ELEM_BLOCK, 1, type, n_elements, per_element, 0, 0, 0);
  ex_put_conn(id, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr);
  const double x[8] = {0, 1, 0, 1, 0, 1, 0, 1}, y[8] = {0, 0, 1, 1, 0, 0, 1, 1},
               z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  ex_put_coord(id, x, y, dim == 3 ? z : nullptr);
  std::vector<char*> lines;
  for (std::string& line : info) lines.push_back(line.data());
  if (!info.empty()) ex_put_info(id, static_cast<int>(lines.size()), lines.data());
  ex_close(id);
  return path;
}

// Info records without the first line "hexadapt metadata" (another writer's, or ours before
// it, which cut a long entry into lines of 80 characters) give no metadata.
TEST(Exodus, InfoRecordsOfOtherWritersAreNotMetadata) {
  const std::string record = "{\"fractions\":[],\"void\":\"\",\"value_tolerance\":0.0001,";
  const std::string path =
      one_block("old_info.exo", 2, "QUAD4", 4, {1, 2, 4, 3},
                {"hexadapt_input: " + record.substr(0, 40), record.substr(40), "a: b"});
  const MeshData r = read_mesh(path);
  std::filesystem::remove(path);
  for (const auto& [key, value] : r.metadata) EXPECT_EQ(key, "hexadapt_materials") << value;
}

// A file of another tool: blocks 20 and 10 (in that order), one named, no `material`
// variable and no element map: the blocks become the materials, in file order.
TEST(Exodus, BlocksOfAnotherToolAreTheMaterials) {
  const std::string path = test::temp_path("foreign.exo");
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  ex_put_init(id, "foreign", 2, 6, 2, 2, 0, 0);
  ex_put_block(id, EX_ELEM_BLOCK, 20, "QUAD4", 1, 4, 0, 0, 0);
  ex_put_block(id, EX_ELEM_BLOCK, 10, "QUAD4", 1, 4, 0, 0, 0);
  const int right[4] = {2, 3, 6, 5}, left[4] = {1, 2, 5, 4};
  ex_put_conn(id, EX_ELEM_BLOCK, 20, right, nullptr, nullptr);
  ex_put_conn(id, EX_ELEM_BLOCK, 10, left, nullptr, nullptr);
  char steel[] = "steel", none[] = "";
  char* names[2] = {steel, none};
  ex_put_names(id, EX_ELEM_BLOCK, names);
  const double x[6] = {0, 1, 2, 0, 1, 2}, y[6] = {0, 0, 0, 1, 1, 1};
  ex_put_coord(id, x, y, nullptr);
  ex_close(id);
  const MeshData r = read_mesh(path);
  EXPECT_EQ(test::cell_ids(r), (std::vector<int>{1, 2, 5, 4, 0, 1, 4, 3}));
  EXPECT_EQ(r.find_cell_array("material")->values, (std::vector<double>{0, 1}));
  bool named = false;
  for (const auto& [k, v] : r.metadata)
    named = named || (k == "hexadapt_materials" && v == "steel,block_10");
  EXPECT_TRUE(named);
  std::filesystem::remove(path);
}

TEST(Exodus, WrongElementsAndNodeIdsAreInputErrors) {
  const auto message = [](const std::string& path) {
    try {
      read_mesh(path);
    } catch (const InputError& e) {
      std::filesystem::remove(path);
      return std::string(e.what());
    }
    std::filesystem::remove(path);
    return std::string("no error");
  };
  EXPECT_NE(message(one_block("tet.exo", 3, "TETRA", 4, {1, 2, 3, 5})).find("TETRA"),
            std::string::npos);
  EXPECT_NE(
      message(one_block("hex_in_2d.exo", 2, "HEX8", 8, {1, 2, 4, 3, 5, 6, 8, 7})).find("only HEX8"),
      std::string::npos);
  EXPECT_NE(message(one_block("far.exo", 3, "HEX8", 8, {1, 2, 4, 3, 5, 6, 8, 99}))
                .find("refers to node 99, outside 1..8"),
            std::string::npos);
  EXPECT_NE(message(one_block("zero.exo", 2, "QUAD4", 4, {1, 2, 4, 0})).find("refers to node 0"),
            std::string::npos);
  // A right HEX8 file reads.
  const std::string ok = one_block("ok.exo", 3, "HEX8", 8, {1, 2, 4, 3, 5, 6, 8, 7});
  EXPECT_EQ(read_mesh(ok).n_cells(), 1);
  std::filesystem::remove(ok);
}

}  // namespace
}  // namespace hexadapt::io
