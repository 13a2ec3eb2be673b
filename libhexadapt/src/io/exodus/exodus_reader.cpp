// Reading Exodus II (what is read is described in hexadapt/io/exodus.h). Every count the
// file declares is checked against the file's size before anything is allocated, and every
// node id against the node count, so a lying or truncated file gives an InputError.
#include <exodusII.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

#include "../time_step.h"
#include "exodus_file.h"
#include "exodus_guard.h"
#include "exodus_info.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"
#include "hexadapt/io/exodus.h"
#include "hexadapt/io/material_names.h"
#include "netcdf_extent.h"

namespace hexadapt::io {

namespace {

using detail::ExodusFile;

// Large enough for any name a netCDF file can hold (NC_MAX_NAME is 256).
constexpr int name_capacity = 256;

struct Header {
  int dim = 0, n_nodes = 0, n_elements = 0, n_blocks = 0;
};

struct Block {
  int id = 0;
  int count = 0;
  std::string name;
};

long long file_bytes(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? static_cast<long long>(st.st_size) : 0;
}

// Sizes that the file cannot hold (each value takes at least 4 bytes) are lies.
void check_size(const ExodusFile& f, const std::string& what, long long count, long long per_item) {
  if (count < 0 || count * per_item * 4 > file_bytes(f.path()))
    throw InputError(f.path(), what,
                     "declares " + std::to_string(count) +
                         " entries, more than the file's size can hold (truncated file?)");
}

// Checked before the netCDF library opens the file (netcdf_extent.h says why): a classic
// header must parse within the file and the data it declares must fit in it. The header is
// looked for in the first 64 MB; a longer one is left to the library.
void check_netcdf_header(const std::string& path) {
  const long long size = file_bytes(path);
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<long long>(size, 64 << 20)), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const detail::NetcdfHeader h = detail::netcdf_header(head);
  if (!h.classic) return;  // netCDF-4 (HDF5) or not netCDF: the library judges
  if (!h.complete && static_cast<long long>(head.size()) == size)
    throw InputError(path, "netCDF header",
                     "malformed or cut short: a count or length runs past the end of the file");
  if (h.complete && h.data_end > static_cast<std::uint64_t>(size))
    throw InputError(path, "",
                     "truncated: the netCDF header declares " + std::to_string(h.data_end) +
                         " bytes of data, the file has " + std::to_string(size));
  // The Exodus library reads these into scalars and an 81-character title buffer.
  for (const auto& [name, values] : h.global_attributes) {
    const bool scalar = name == "version" || name == "api_version" ||
                        name == "floating_point_word_size" || name == "file_size" ||
                        name == "maximum_name_length" || name == "int64_status";
    if ((scalar && values != 1) || (name == "title" && values > MAX_LINE_LENGTH))
      throw InputError(path, "global attribute " + name,
                       std::to_string(values) + " values, more than Exodus II allows");
  }
}

Header read_header(const ExodusFile& f) {
  char title[MAX_LINE_LENGTH + 1] = {};
  Header h;
  int n_node_sets = 0, n_side_sets = 0;
  f.check(ex_get_init(f.id(), title, &h.dim, &h.n_nodes, &h.n_elements, &h.n_blocks, &n_node_sets,
                      &n_side_sets),
          "header");
  if (h.dim != 2 && h.dim != 3)
    throw InputError(
        f.path(), "header",
        "num_dim is " + std::to_string(h.dim) + ": only 2 (quads) or 3 (hexes) is read");
  if (h.n_elements <= 0 || h.n_blocks <= 0 || h.n_nodes <= 0)
    throw InputError(f.path(), "header", "no elements: nothing to read");
  check_size(f, "nodes", h.n_nodes, h.dim);
  check_size(f, "elements", h.n_elements, h.dim == 3 ? 8 : 4);
  check_size(f, "element blocks", h.n_blocks, 1);
  return h;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<Block> read_blocks(const ExodusFile& f, const Header& h) {
  std::vector<int> ids(static_cast<std::size_t>(h.n_blocks));
  detail::check_variable_size(f, "eb_prop1", ids.size());
  f.check(ex_get_ids(f.id(), EX_ELEM_BLOCK, ids.data()), "element block ids");
  for (std::size_t k = 0; k < ids.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (ids[j] == ids[k])
        throw InputError(f.path(), "element blocks",
                         "two blocks with id " + std::to_string(ids[k]));
  detail::check_string_length(f, "eb_names", name_capacity + 1);
  std::vector<std::vector<char>> buffers(ids.size(), std::vector<char>(name_capacity + 1, '\0'));
  std::vector<char*> names;
  for (auto& b : buffers) names.push_back(b.data());
  f.check(ex_set_max_name_length(f.id(), name_capacity), "names");
  f.check(ex_get_names(f.id(), EX_ELEM_BLOCK, names.data()), "element block names");
  std::vector<Block> blocks;
  long long total = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, per_element = 0, edges = 0, faces = 0, attributes = 0;
    const std::string where = "element block " + std::to_string(ids[k]);
    detail::check_attribute_length(f, "connect" + std::to_string(k + 1), "elem_type",
                                   MAX_STR_LENGTH);
    f.check(ex_get_block(f.id(), EX_ELEM_BLOCK, ids[k], type, &count, &per_element, &edges, &faces,
                         &attributes),
            where);
    const std::string t = upper(type);
    const bool ok = h.dim == 3
                        ? t.rfind("HEX", 0) == 0 && per_element == 8
                        : (t.rfind("QUAD", 0) == 0 || t.rfind("SHELL", 0) == 0) && per_element == 4;
    if (count > 0 && !ok)
      throw InputError(f.path(), where,
                       "elements of type " + quote_token(type) + " with " +
                           std::to_string(per_element) +
                           " nodes: only HEX8 (num_dim 3) and "
                           "QUAD4 (num_dim 2) elements are read");
    if (count < 0) throw InputError(f.path(), where, "negative element count");
    total += count;
    std::string name = buffers[k].data();
    if (name.empty()) name = "block_" + std::to_string(ids[k]);
    blocks.push_back({ids[k], count, name});
  }
  if (total != h.n_elements)
    throw InputError(f.path(), "element blocks",
                     "hold " + std::to_string(total) + " elements, the header says " +
                         std::to_string(h.n_elements));
  return blocks;
}

void read_cells(const ExodusFile& f, const Header& h, const std::vector<Block>& blocks,
                MeshData& d) {
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  d.cells.reserve(static_cast<std::size_t>(h.n_elements) * npc);
  for (std::size_t position = 0; position < blocks.size(); ++position) {
    const Block& b = blocks[position];
    if (b.count == 0) continue;
    const std::string where = "element block " + std::to_string(b.id);
    std::vector<int> conn(static_cast<std::size_t>(b.count) * npc);
    detail::read_int_variable(f, "connect" + std::to_string(position + 1), conn);
    for (std::size_t e = 0; e < static_cast<std::size_t>(b.count); ++e)
      for (std::size_t k = 0; k < npc; ++k) {
        const std::size_t from =
            d.dim == 3 ? static_cast<std::size_t>(ref_hex::vtk_of_binary[k]) : k;
        const int node = conn[e * npc + from];
        if (node < 1 || node > h.n_nodes)
          throw InputError(f.path(), where,
                           "element " + std::to_string(e + 1) + " refers to node " +
                               std::to_string(node) + ", outside 1.." + std::to_string(h.n_nodes));
        d.cells.emplace_back(node - 1);
      }
  }
}

void read_points(const ExodusFile& f, const Header& h, MeshData& d) {
  std::vector<double> xyz[3];
  for (int k = 0; k < 3; ++k) xyz[k].assign(static_cast<std::size_t>(h.n_nodes), 0.0);
  const auto n = static_cast<std::size_t>(h.n_nodes);
  detail::check_variable_size(f, "coord", static_cast<std::size_t>(h.dim) * n, false);
  for (const char* axis : {"coordx", "coordy", "coordz"})
    if (axis[5] != 'z' || h.dim == 3) detail::check_variable_size(f, axis, n, false);
  f.check(ex_get_coord(f.id(), xyz[0].data(), xyz[1].data(), h.dim == 3 ? xyz[2].data() : nullptr),
          "coordinates");
  d.points.resize(static_cast<std::size_t>(h.n_nodes));
  for (std::size_t v = 0; v < d.points.size(); ++v)
    d.points[v] = Vec3(xyz[0][v], xyz[1][v], xyz[2][v]);
}

std::vector<std::string> variable_names(const ExodusFile& f, ex_entity_type type, int n) {
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(n),
                                         std::vector<char>(name_capacity + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  detail::check_string_length(f, type == EX_NODAL ? "name_nod_var" : "name_elem_var",
                              name_capacity + 1);
  if (n > 0) f.check(ex_get_variable_names(f.id(), type, n, pointers.data()), "variable names");
  std::vector<std::string> out;
  for (int k = 0; k < n; ++k) {
    std::string name = buffers[static_cast<std::size_t>(k)].data();
    if (name.empty()) name = (type == EX_NODAL ? "nodal_" : "element_") + std::to_string(k + 1);
    for (const std::string& old : out)
      if (old == name)
        throw InputError(f.path(), "variables", "two variables named " + quote_token(name));
    out.push_back(name);
  }
  return out;
}

int variable_count(const ExodusFile& f, ex_entity_type type) {
  int n = 0;
  f.check(ex_get_variable_param(f.id(), type, &n), "variables");
  if (n < 0 || n > 100000) throw InputError(f.path(), "variables", "implausible variable count");
  return n;
}

// The type the file stores its variables as (the library reads them as double either way):
// kept in the arrays, as the precision of the values (fractions.h) depends on it.
ScalarType stored_type(const ExodusFile& f) {
  return f.stored_float_size() == 4 ? ScalarType::float32 : ScalarType::float64;
}

// Element variables of one step, as cell arrays; a variable a block lacks (truth table) is 0
// on that block's cells.
void read_element_variables(const ExodusFile& f, const std::vector<Block>& blocks, int step,
                            MeshData& d) {
  const int n = variable_count(f, EX_ELEM_BLOCK);
  if (n == 0) return;
  check_size(f, "element variables", static_cast<long long>(n) * d.n_cells(), 1);
  const std::vector<std::string> names = variable_names(f, EX_ELEM_BLOCK, n);
  const auto nb = static_cast<std::size_t>(blocks.size());
  std::vector<int> table(nb * static_cast<std::size_t>(n), 1);
  detail::check_variable_size(f, "elem_var_tab", table.size(), false);
  f.check(ex_get_truth_table(f.id(), EX_ELEM_BLOCK, static_cast<int>(nb), n, table.data()),
          "element variable truth table");
  for (int k = 0; k < n; ++k) {
    DataArray a{names[static_cast<std::size_t>(k)], 1, stored_type(f), {}};
    a.values.reserve(static_cast<std::size_t>(d.n_cells()));
    for (std::size_t b = 0; b < nb; ++b) {
      const auto count = static_cast<std::size_t>(blocks[b].count);
      std::vector<double> values(count, 0.0);
      if (count > 0 && table[b * static_cast<std::size_t>(n) + static_cast<std::size_t>(k)] != 0)
        f.check(ex_get_var(f.id(), step, EX_ELEM_BLOCK, k + 1, blocks[b].id,
                           static_cast<int64_t>(count), values.data()),
                "element variable " + quote_token(a.name) + " on block " +
                    std::to_string(blocks[b].id));
      a.values.insert(a.values.end(), values.begin(), values.end());
    }
    d.set_cell_array(std::move(a));
  }
}

void read_nodal_variables(const ExodusFile& f, int step, MeshData& d) {
  const int n = variable_count(f, EX_NODAL);
  if (n == 0) return;
  check_size(f, "nodal variables", static_cast<long long>(n) * d.n_points(), 1);
  const std::vector<std::string> names = variable_names(f, EX_NODAL, n);
  for (int k = 0; k < n; ++k) {
    DataArray a{names[static_cast<std::size_t>(k)], 1, stored_type(f),
                std::vector<double>(d.points.size(), 0.0)};
    f.check(ex_get_var(f.id(), step, EX_NODAL, k + 1, 1, d.n_points(), a.values.data()),
            "nodal variable " + quote_token(a.name));
    d.set_point_array(std::move(a));
  }
}

// Three scalar variables P_x, P_y, P_z (or _X, _Y, _Z) in a row become the 3-component
// array P, as the writer split it (and as ParaView's Exodus reader shows it).
void group_vectors(std::vector<DataArray>& arrays) {
  const auto suffix = [](const std::string& name, char axis) {
    const std::size_t n = name.size();
    return n > 2 && name[n - 2] == '_' &&
           std::toupper(static_cast<unsigned char>(name[n - 1])) == axis;
  };
  std::vector<DataArray> out;
  for (std::size_t k = 0; k < arrays.size(); ++k) {
    const std::string& x = arrays[k].name;
    const std::string base = x.substr(0, x.size() < 2 ? 0 : x.size() - 2);
    if (k + 2 < arrays.size() && suffix(x, 'X') && suffix(arrays[k + 1].name, 'Y') &&
        suffix(arrays[k + 2].name, 'Z') && arrays[k + 1].name.compare(0, base.size(), base) == 0 &&
        arrays[k + 2].name.compare(0, base.size(), base) == 0 &&
        arrays[k + 1].name.size() == x.size() && arrays[k + 2].name.size() == x.size()) {
      DataArray v{base, 3, arrays[k].type, {}};
      const std::size_t n = arrays[k].values.size();
      v.values.reserve(3 * n);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t c = 0; c < 3; ++c) v.values.push_back(arrays[k + c].values[i]);
      out.push_back(std::move(v));
      k += 2;
    } else {
      out.push_back(std::move(arrays[k]));
    }
  }
  arrays = std::move(out);
}

std::vector<double> read_times(const ExodusFile& f) {
  const int64_t n = ex_inquire_int(f.id(), EX_INQ_TIME);
  if (n < 0) f.check(static_cast<int>(n), "time steps");
  check_size(f, "time steps", n, 1);
  std::vector<double> times(static_cast<std::size_t>(n));
  detail::check_variable_size(f, "time_whole", times.size(), n > 0);
  if (n > 0) f.check(ex_get_all_times(f.id(), times.data()), "time values");
  return times;
}

// The info records as metadata (exodus_info.h).
void read_info(const ExodusFile& f, MeshData& d) {
  const int64_t n = ex_inquire_int(f.id(), EX_INQ_INFO);
  if (n < 0) f.check(static_cast<int>(n), "info records");
  check_size(f, "info records", n, (MAX_LINE_LENGTH + 1) / 4);  // characters, not 4-byte values
  if (n == 0) return;
  const std::size_t width = MAX_LINE_LENGTH + 1;
  detail::check_variable_size(f, "info_records", static_cast<std::size_t>(n) * width);
  detail::check_string_length(f, "info_records", width);
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(n),
                                         std::vector<char>(width + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  f.check(ex_get_info(f.id(), pointers.data()), "info records");
  std::vector<std::string> lines;  // a line's characters, without the spaces filling its row
  for (const auto& b : buffers) {
    std::string line(b.begin(), std::find(b.begin(), b.begin() + MAX_LINE_LENGTH, '\0'));
    line.erase(line.find_last_not_of(' ') + 1);
    lines.push_back(std::move(line));
  }
  d.metadata = detail::metadata_of_info(lines);
}

// The block of each cell as the `material` array, the block names as the materials; when
// the file has its own `material` variable (our files), block id - 1 is the material index.
void block_materials(const std::vector<Block>& blocks, MeshData& d) {
  std::vector<std::string> names;
  if (d.find_cell_array("material") == nullptr) {
    DataArray m{"material", 1, ScalarType::int32, {}};
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      m.values.insert(m.values.end(), static_cast<std::size_t>(blocks[b].count),
                      static_cast<double>(b));
      names.push_back(blocks[b].name);
    }
    d.set_cell_array(std::move(m));
  } else {
    for (const Block& b : blocks) {
      if (b.id < 1 || b.id > 100000) return;
      const auto m = static_cast<std::size_t>(b.id - 1);
      while (names.size() <= m) names.push_back("material_" + std::to_string(names.size()));
      names[m] = b.name;
    }
  }
  set_material_names(d, names);
}

// The cells back in their own order when the element id map is a permutation of 1..n (our
// files number the cells so); file order otherwise.
void restore_cell_order(const ExodusFile& f, MeshData& d) {
  const auto n = static_cast<std::size_t>(d.n_cells());
  std::vector<int> map(n);
  detail::check_variable_size(f, "elem_num_map", n, false);
  f.check(ex_get_id_map(f.id(), EX_ELEM_MAP, map.data()), "element id map");
  std::vector<char> seen(n, 0);
  for (int id : map) {
    if (id < 1 || static_cast<std::size_t>(id) > n || seen[static_cast<std::size_t>(id - 1)])
      return;
    seen[static_cast<std::size_t>(id - 1)] = 1;
  }
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  std::vector<NodeId> cells(d.cells.size(), NodeId(0));
  // Cell arrays are still scalars here: vectors are grouped after the reordering.
  for (std::size_t e = 0; e < n; ++e)
    std::copy_n(
        d.cells.begin() + static_cast<std::ptrdiff_t>(e * npc), npc,
        cells.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(map[e] - 1) * npc));
  d.cells = std::move(cells);
  for (DataArray& a : d.cell_data) {
    std::vector<double> values(a.values.size());
    for (std::size_t e = 0; e < n; ++e) values[static_cast<std::size_t>(map[e] - 1)] = a.values[e];
    a.values = std::move(values);
  }
}

}  // namespace

MeshData read_exodus(const std::string& path, const ReadOptions& options) {
  if (file_bytes(path) > 0) check_netcdf_header(path);
  const ExodusFile f = ExodusFile::open(path);
  const Header h = read_header(f);
  MeshData d;
  d.dim = h.dim;
  const std::vector<Block> blocks = read_blocks(f, h);
  read_cells(f, h, blocks, d);
  read_points(f, h, d);
  read_info(f, d);
  const std::vector<double> times = read_times(f);
  const std::size_t step = detail::select_time_step(times, options, path);
  if (!times.empty()) {
    read_element_variables(f, blocks, static_cast<int>(step) + 1, d);
    read_nodal_variables(f, static_cast<int>(step) + 1, d);
  }
  block_materials(blocks, d);
  restore_cell_order(f, d);
  group_vectors(d.cell_data);
  group_vectors(d.point_data);
  return d;
}

}  // namespace hexadapt::io
