// A .pvtu's pieces merged on the ranks of an MPI job (run under mpirun -np N): each rank reads
// its share of the pieces, and the merged mesh gathered by its global ids must be the one
// read_mesh gives on one process, to the bit: the same points welded (copies within the
// tolerance, chains of copies each within the tolerance of the previous), the same cells
// dropped (ghosts, a cell two pieces give), the same numbering, the same errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"
#include "hexadapt/io/vtk_collection.h"
#include "hexadapt/mesh/structured.h"
#include "slab_case.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;

constexpr int nx = 5, ny = 4, nz = 3;

// A folder of this job's own (rank 0's process id), made by rank 0, removed at the end.
class JobFolder {
 public:
  JobFolder() {
    const std::vector<std::int64_t> pid =
        dist::all_gather_values(test::world(), std::vector<std::int64_t>{::getpid()});
    path_ = fs::temp_directory_path() / ("hexadapt_pieces_" + std::to_string(pid[0]) + "_" +
                                         std::to_string(test::world().size()));
    if (test::world().rank() == 0) fs::create_directories(path_);
    sync();
  }
  ~JobFolder() {
    sync();
    if (test::world().rank() == 0) fs::remove_all(path_);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  static void sync() { dist::all_gather_values(test::world(), std::vector<int>{0}); }

 private:
  fs::path path_;
};

// A grid point's own small offset (< 0.02), so that the copies of points fall at every place
// relative to the weld's buckets (two copies often in different buckets).
Vec3 jitter(index_t g) {
  const auto f = [g](int m) {
    return static_cast<double>((static_cast<long>(g) * m) % 101) * 2e-4;
  };
  return {f(7919), f(104729), f(1299709)};
}

// The unit grid's cells [first, end) as a piece of their own, with a point array and two cell
// arrays; `ghost` marks its last cell as another piece's. Its copy of a point is moved along
// x by 0.6 times the tolerance (1e-6 x the unit edge) for each copy before it (`copies`, per
// grid point), so that each copy welds to the one before only and the chains lead to the
// first; a ghost cell's own points count no copy (they are dropped).
io::MeshData piece(int first, int end, std::vector<int>& copies, bool ghost) {
  std::vector<NodeId> all;
  append_structured_cells(nx, ny, nz, all);
  io::MeshData d;
  d.dim = 3;
  std::vector<index_t> local(copies.size(), -1);
  io::DataArray vf{"vf_a", 1, io::ScalarType::float64, {}};
  io::DataArray id{"source", 1, io::ScalarType::int32, {}};
  io::DataArray t{"temperature", 1, io::ScalarType::float64, {}};
  for (int c = first; c < end; ++c) {
    const bool counted = !(ghost && c + 1 == end);
    for (int v = 0; v < 8; ++v) {
      const NodeId g = all[static_cast<std::size_t>(c * 8 + v)];
      index_t& l = local[g.idx()];
      if (l < 0) {
        l = static_cast<index_t>(d.points.size());
        const int i = g.value() % (nx + 1), j = g.value() / (nx + 1) % (ny + 1),
                  k = g.value() / ((nx + 1) * (ny + 1));
        const double shift = copies[g.idx()] * 0.6e-6;
        if (counted) ++copies[g.idx()];
        d.points.push_back(Vec3(i + shift, j, k) + jitter(g.value()));
        t.values.push_back(g.value() + 1e6 * shift);
      }
      d.cells.push_back(NodeId(l));
    }
    vf.values.push_back(c / 60.0);
    id.values.push_back(c);
  }
  d.cell_data = {vf, id};
  d.point_data = {t};
  if (ghost) {
    io::DataArray g{"vtkGhostType", 1, io::ScalarType::uint8, {}};
    g.values.assign(static_cast<std::size_t>(end - first), 0);
    g.values.back() = 1;
    d.cell_data.push_back(g);
  }
  return d;
}

std::vector<int> no_copies() {
  return std::vector<int>(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)), 0);
}

void write_pvtu(const std::string& path, const std::vector<std::string>& pieces) {
  std::ofstream f(path);
  f << R"(<VTKFile type="PUnstructuredGrid" version="1.0"><PUnstructuredGrid GhostLevel="0">
<PCellData><PDataArray type="Float64" Name="vf_a"/><PDataArray type="Int32" Name="source"/></PCellData>
<PPointData><PDataArray type="Float64" Name="temperature"/></PPointData>
<PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>)";
  for (const auto& p : pieces) f << "<Piece Source=\"" << p << "\"/>";
  f << "</PUnstructuredGrid></VTKFile>\n";
}

constexpr const char* empty_vtu =
    R"(<VTKFile type="UnstructuredGrid" version="1.0"><UnstructuredGrid>
<Piece NumberOfPoints="0" NumberOfCells="0"><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii"></DataArray></Points>
<Cells><DataArray type="Int64" Name="connectivity" format="ascii"></DataArray>
<DataArray type="Int64" Name="offsets" format="ascii"></DataArray>
<DataArray type="UInt8" Name="types" format="ascii"></DataArray></Cells></Piece></UnstructuredGrid></VTKFile>
)";

// Seven pieces of the 60 cells (points moved as piece() says) and an empty one: piece 3 gives
// its last cell as a ghost (piece 4 owns it), and the last piece gives cell 0 again (piece 0
// has it).
std::string write_case(const JobFolder& folder, const std::string& name,
                       const io::MeshData* replace_piece5 = nullptr) {
  const std::string pvtu = folder.file(name + ".pvtu");
  std::vector<std::string> names;
  if (test::world().rank() == 0) {
    const int cuts[] = {0, 9, 17, 26, 35, 43, 52, 60};
    std::vector<int> copies = no_copies();
    for (int k = 0; k < 7; ++k) {
      const bool ghost = k == 3;
      io::MeshData p = piece(cuts[k], cuts[k + 1] + (ghost ? 1 : 0), copies, ghost);
      if (k == 5 && replace_piece5) p = *replace_piece5;
      if (k == 6) {
        const io::MeshData first = piece(0, 1, copies, false);
        const index_t shift = p.n_points();
        p.points.insert(p.points.end(), first.points.begin(), first.points.end());
        for (NodeId n : first.cells) p.cells.push_back(NodeId(n.value() + shift));
        for (std::size_t a = 0; a < p.cell_data.size(); ++a)
          p.cell_data[a].values.push_back(first.cell_data[a].values[0]);
        p.point_data[0].values.insert(p.point_data[0].values.end(),
                                      first.point_data[0].values.begin(),
                                      first.point_data[0].values.end());
      }
      io::write_mesh(p, folder.file(name + "_" + std::to_string(k) + ".vtu"));
    }
    std::ofstream(folder.file(name + "_empty.vtu")) << empty_vtu;
  }
  for (int k = 0; k < 7; ++k) {
    names.push_back(name + "_" + std::to_string(k) + ".vtu");
    if (k == 2) names.push_back(name + "_empty.vtu");
  }
  if (test::world().rank() == 0) write_pvtu(pvtu, names);
  JobFolder::sync();
  return pvtu;
}

io::MeshPart merged_on_ranks(const std::string& path, const io::ReadOptions& options = {}) {
  const dist::Communicator& comm = test::world();
  return io::merge_rank_pieces(comm, io::read_rank_pieces(path, options, comm.rank(), comm.size()),
                               options);
}

// Every rank's part put together by the global ids: the points and point arrays at their
// ids, the cells (as global node ids) and cell arrays in rank order.
io::MeshData gathered(const io::MeshPart& part) {
  const dist::Communicator& comm = test::world();
  io::MeshData whole;
  whole.dim = part.data.dim;
  std::vector<std::int64_t> cells;
  for (NodeId n : part.data.cells) cells.push_back(part.node_ids[n.idx()]);
  for (std::int64_t n : dist::all_gather_values(comm, cells))
    whole.cells.push_back(NodeId(static_cast<index_t>(n)));
  const std::vector<std::int64_t> ids = dist::all_gather_values(comm, part.node_ids);
  std::vector<double> xyz;
  for (const Vec3& p : part.data.points) xyz.insert(xyz.end(), p.data(), p.data() + 3);
  const std::vector<double> all_xyz = dist::all_gather_values(comm, xyz);
  whole.points.resize(static_cast<std::size_t>(part.n_nodes));
  for (std::size_t i = 0; i < ids.size(); ++i)
    whole.points[static_cast<std::size_t>(ids[i])] =
        Vec3(all_xyz[3 * i], all_xyz[3 * i + 1], all_xyz[3 * i + 2]);
  for (const io::DataArray& a : part.data.cell_data) {
    io::DataArray w = a;
    w.values = dist::all_gather_values(comm, a.values);
    whole.cell_data.push_back(std::move(w));
  }
  for (const io::DataArray& a : part.data.point_data) {
    io::DataArray w = a;
    const std::vector<double> values = dist::all_gather_values(comm, a.values);
    w.values.assign(static_cast<std::size_t>(part.n_nodes), 0);
    for (std::size_t i = 0; i < ids.size(); ++i)
      w.values[static_cast<std::size_t>(ids[i])] = values[i];
    whole.point_data.push_back(std::move(w));
  }
  return whole;
}

void expect_same_mesh(const io::MeshData& a, const io::MeshData& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.points, b.points);
  ASSERT_EQ(a.cell_data.size(), b.cell_data.size());
  for (std::size_t i = 0; i < a.cell_data.size(); ++i) {
    EXPECT_EQ(a.cell_data[i].name, b.cell_data[i].name);
    EXPECT_EQ(a.cell_data[i].type, b.cell_data[i].type);
    EXPECT_EQ(a.cell_data[i].values, b.cell_data[i].values);
  }
  ASSERT_EQ(a.point_data.size(), b.point_data.size());
  for (std::size_t i = 0; i < a.point_data.size(); ++i) {
    EXPECT_EQ(a.point_data[i].name, b.point_data[i].name);
    EXPECT_EQ(a.point_data[i].values, b.point_data[i].values);
  }
}

TEST(PiecesOnRanks, MergedAsOnOneProcess) {
  const JobFolder folder;
  const std::string path = write_case(folder, "grid");
  const io::MeshData serial = io::read_mesh(path);
  // The known answer: the unit grid's 120 points (every chain of copies welded to piece 0's),
  // its 60 cells (the ghost and the repeat dropped).
  EXPECT_EQ(serial.n_points(), (nx + 1) * (ny + 1) * (nz + 1));
  EXPECT_EQ(serial.n_cells(), nx * ny * nz);
  const io::MeshPart part = merged_on_ranks(path);
  EXPECT_EQ(part.n_cells, serial.n_cells());
  EXPECT_EQ(part.n_nodes, serial.n_points());
  EXPECT_EQ(dist::sum_in_rank_order(test::world(), static_cast<std::int64_t>(part.data.n_cells())),
            part.n_cells);
  // The ranks' cells tile the merged mesh's in rank order.
  const std::vector<std::int64_t> ids = dist::all_gather_values(test::world(), part.cell_ids);
  ASSERT_EQ(ids.size(), static_cast<std::size_t>(part.n_cells));
  for (std::size_t c = 0; c < ids.size(); ++c) EXPECT_EQ(ids[c], static_cast<std::int64_t>(c));
  EXPECT_TRUE(std::is_sorted(part.node_ids.begin(), part.node_ids.end()));
  expect_same_mesh(gathered(part), serial);
  // A tolerance below the shifts: nothing welds across pieces, as on one process.
  io::ReadOptions fine;
  fine.weld_tolerance = 1e-8;
  const io::MeshData apart = io::read_mesh(path, fine);
  EXPECT_GT(apart.n_points(), serial.n_points());
  expect_same_mesh(gathered(merged_on_ranks(path, fine)), apart);
}

TEST(PiecesOnRanks, FewerPiecesThanRanks) {
  const JobFolder folder;
  const std::string path = folder.file("two.pvtu");
  if (test::world().rank() == 0) {
    std::vector<int> copies = no_copies();
    io::write_mesh(piece(0, 30, copies, false), folder.file("two_0.vtu"));
    io::write_mesh(piece(30, 60, copies, false), folder.file("two_1.vtu"));
    write_pvtu(path, {"two_0.vtu", "two_1.vtu"});
  }
  JobFolder::sync();
  const io::MeshPart part = merged_on_ranks(path);
  EXPECT_EQ(part.n_cells, nx * ny * nz);
  expect_same_mesh(gathered(part), io::read_mesh(path));
}

TEST(PiecesOnRanks, APieceOfOtherArraysIsTheSameErrorOnEveryRank) {
  const JobFolder folder;
  std::vector<int> copies = no_copies();
  io::MeshData odd = piece(43, 52, copies, false);
  odd.point_data.clear();
  const std::string path = write_case(folder, "odd", &odd);
  std::string serial;
  try {
    io::read_mesh(path);
  } catch (const InputError& e) {
    serial = e.what();
  }
  ASSERT_NE(serial.find("temperature"), std::string::npos) << serial;
  try {
    merged_on_ranks(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.what(), serial);
  }
}

}  // namespace
}  // namespace hexadapt
