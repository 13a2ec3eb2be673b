// Writing Exodus II (layout in hexadapt/io/exodus.h): the sets and the element order are
// computed first, since ex_put_init needs every count, then the file is written in the
// order the Exodus API defines it: blocks, coordinates, maps, sets, records, variables.
#include <exodusII.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "exodus_file.h"
#include "exodus_info.h"
#include "exodus_sets.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/geometry.h"
#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/exodus.h"
#include "hexadapt/io/material_names.h"

namespace hexadapt::io {

namespace {

using detail::ExodusFile;

struct Blocks {
  std::vector<int> material;         // per cell
  std::vector<std::string> names;    // per material
  std::vector<index_t> order;        // cells in element order (grouped by material)
  std::vector<int> element_of_cell;  // 1-based element number of each cell
  std::vector<int> used;             // materials with cells, increasing
  std::vector<index_t> count;        // cells per material
};

Blocks group_cells(const MeshData& d, const std::string& path) {
  Blocks b;
  const auto n = static_cast<std::size_t>(d.n_cells());
  b.names = material_names(d);
  b.material.assign(n, 0);
  if (const DataArray* a = d.find_cell_array("material"); a != nullptr && a->n_components == 1) {
    for (std::size_t c = 0; c < n; ++c) {
      const double v = a->values[c];
      if (!(v >= 0 && v == std::floor(v) && v < 1e6))
        throw OptionError(path + ": cell " + std::to_string(c) + " has material " +
                          std::to_string(v) + ", not a material index");
      b.material[c] = static_cast<int>(v);
    }
  } else if (b.names.empty()) {
    b.names.push_back("block_1");
  }
  const int n_mat = n == 0 ? 0 : *std::max_element(b.material.begin(), b.material.end()) + 1;
  for (int m = static_cast<int>(b.names.size()); m < n_mat; ++m)
    b.names.push_back("material_" + std::to_string(m));
  b.count.assign(b.names.size(), 0);
  for (int m : b.material) ++b.count[static_cast<std::size_t>(m)];
  for (std::size_t m = 0; m < b.count.size(); ++m)
    if (b.count[m] > 0) b.used.push_back(static_cast<int>(m));
  b.order.resize(n);
  for (std::size_t c = 0; c < n; ++c) b.order[c] = static_cast<index_t>(c);
  std::stable_sort(b.order.begin(), b.order.end(), [&](index_t x, index_t y) {
    return b.material[static_cast<std::size_t>(x)] < b.material[static_cast<std::size_t>(y)];
  });
  b.element_of_cell.resize(n);
  for (std::size_t e = 0; e < n; ++e)
    b.element_of_cell[static_cast<std::size_t>(b.order[e])] = static_cast<int>(e) + 1;
  return b;
}

// The Exodus API takes names as char* arrays.
struct NameList {
  explicit NameList(std::vector<std::string> names) : text(std::move(names)) {
    for (std::string& s : text) pointers.push_back(s.data());
  }
  char** data() { return pointers.data(); }
  std::vector<std::string> text;
  std::vector<char*> pointers;
};

void write_blocks(const ExodusFile& f, const MeshData& d, const Blocks& b) {
  const bool hex = d.dim == 3;
  const auto npc = static_cast<std::size_t>(d.nodes_per_cell());
  std::size_t first = 0;
  std::vector<std::string> names;
  for (int m : b.used) {
    const auto count = static_cast<std::size_t>(b.count[static_cast<std::size_t>(m)]);
    const std::string what = "element block " + std::to_string(m + 1);
    f.check(ex_put_block(f.id(), EX_ELEM_BLOCK, m + 1, hex ? "HEX8" : "QUAD4",
                         static_cast<int64_t>(count), static_cast<int64_t>(npc), 0, 0, 0),
            what);
    std::vector<int> conn;
    conn.reserve(count * npc);
    for (std::size_t e = first; e < first + count; ++e) {
      const std::size_t base = static_cast<std::size_t>(b.order[e]) * npc;
      for (std::size_t k = 0; k < npc; ++k) {
        // HEX8 numbers its nodes as VTK_HEXAHEDRON does; QUAD4 as VTK_QUAD.
        const std::size_t from = hex ? static_cast<std::size_t>(ref_hex::vtk_of_binary[k]) : k;
        conn.push_back(static_cast<int>(d.cells[base + from].value()) + 1);
      }
    }
    f.check(ex_put_conn(f.id(), EX_ELEM_BLOCK, m + 1, conn.data(), nullptr, nullptr), what);
    names.push_back(b.names[static_cast<std::size_t>(m)]);
    first += count;
  }
  NameList list(std::move(names));
  f.check(ex_put_names(f.id(), EX_ELEM_BLOCK, list.data()), "element block names");
}

void write_coordinates(const ExodusFile& f, const MeshData& d) {
  std::vector<double> xyz[3];
  for (const Vec3& p : d.points)
    for (int k = 0; k < 3; ++k) xyz[k].push_back(p[k]);
  f.check(ex_put_coord(f.id(), xyz[0].data(), xyz[1].data(), d.dim == 3 ? xyz[2].data() : nullptr),
          "coordinates");
  NameList names({"x", "y", "z"});
  f.check(ex_put_coord_names(f.id(), names.data()), "coordinate names");
}

void write_maps(const ExodusFile& f, const MeshData& d, const Blocks& b) {
  std::vector<int> nodes(d.points.size());
  for (std::size_t v = 0; v < nodes.size(); ++v) nodes[v] = static_cast<int>(v) + 1;
  f.check(ex_put_id_map(f.id(), EX_NODE_MAP, nodes.data()), "node id map");
  std::vector<int> elements;
  for (index_t c : b.order) elements.push_back(static_cast<int>(c) + 1);
  f.check(ex_put_id_map(f.id(), EX_ELEM_MAP, elements.data()), "element id map");
}

void write_sets(const ExodusFile& f, const detail::MeshSets& sets) {
  std::vector<std::string> names;
  for (std::size_t s = 0; s < sets.side_sets.size(); ++s) {
    const detail::SideSet& set = sets.side_sets[s];
    const auto id = static_cast<ex_entity_id>(s + 1);
    f.check(ex_put_set_param(f.id(), EX_SIDE_SET, id, static_cast<int64_t>(set.elements.size()), 0),
            "side set " + set.name);
    if (!set.elements.empty())
      f.check(ex_put_set(f.id(), EX_SIDE_SET, id, set.elements.data(), set.sides.data()),
              "side set " + set.name);
    names.push_back(set.name);
  }
  if (!names.empty()) {
    NameList list(std::move(names));
    f.check(ex_put_names(f.id(), EX_SIDE_SET, list.data()), "side set names");
  }
  names.clear();
  for (std::size_t s = 0; s < sets.node_sets.size(); ++s) {
    const detail::NodeSet& set = sets.node_sets[s];
    const auto id = static_cast<ex_entity_id>(s + 1);
    f.check(ex_put_set_param(f.id(), EX_NODE_SET, id, static_cast<int64_t>(set.nodes.size()), 0),
            "node set " + set.name);
    if (!set.nodes.empty())
      f.check(ex_put_set(f.id(), EX_NODE_SET, id, set.nodes.data(), nullptr),
              "node set " + set.name);
    names.push_back(set.name);
  }
  if (!names.empty()) {
    NameList list(std::move(names));
    f.check(ex_put_names(f.id(), EX_NODE_SET, list.data()), "node set names");
  }
}

std::string metadata_value(const MeshData& d, const std::string& key, const std::string& fallback) {
  for (const auto& [k, v] : d.metadata)
    if (k == key) return v;
  return fallback;
}

// One QA record (code, version, date, time): the date and time stay empty so that the
// same mesh gives the same bytes; info records carry the metadata.
void write_records(const ExodusFile& f, const MeshData& d) {
  std::string qa[4] = {metadata_value(d, "hexadapt_tool", "hexadapt"),
                       metadata_value(d, "hexadapt_version", HEXADAPT_VERSION), "", ""};
  for (std::string& s : qa) s = s.substr(0, MAX_STR_LENGTH);
  char* record[1][4] = {{qa[0].data(), qa[1].data(), qa[2].data(), qa[3].data()}};
  f.check(ex_put_qa(f.id(), 1, record), "QA record");
  // Each line fills its row: the library writes a line's characters only, and the rest of a
  // row keeps what its buffer held before (the tail of a longer line).
  std::vector<std::string> lines = detail::info_lines(d.metadata, MAX_LINE_LENGTH);
  for (std::string& line : lines) line.resize(MAX_LINE_LENGTH, ' ');
  if (lines.empty()) return;
  NameList list(std::move(lines));
  f.check(ex_put_info(f.id(), static_cast<int>(list.text.size()), list.data()), "info records");
}

// Arrays as scalar variables: one per component, with _x, _y, _z suffixes for vectors.
struct Variable {
  std::string name;
  const DataArray* array;
  int component;
};

std::vector<Variable> variables(const std::vector<DataArray>& arrays) {
  std::vector<Variable> out;
  for (const DataArray& a : arrays)
    for (int k = 0; k < a.n_components; ++k) {
      std::string name = a.name;
      if (a.n_components == 3)
        name += std::string("_") + "xyz"[k];
      else if (a.n_components > 1)
        name += "_" + std::to_string(k);
      out.push_back({name, &a, k});
    }
  return out;
}

void declare_variables(const ExodusFile& f, ex_entity_type type, const std::vector<Variable>& vars,
                       int n_blocks) {
  if (vars.empty()) return;
  const std::string what = type == EX_NODAL ? "nodal variables" : "element variables";
  f.check(ex_put_variable_param(f.id(), type, static_cast<int>(vars.size())), what);
  std::vector<std::string> names;
  for (const Variable& v : vars) names.push_back(v.name);
  NameList list(std::move(names));
  f.check(ex_put_variable_names(f.id(), type, static_cast<int>(vars.size()), list.data()), what);
  if (type == EX_NODAL) return;
  // Every variable on every block: defined once, not one file redefinition per call.
  std::vector<int> table(vars.size() * static_cast<std::size_t>(n_blocks), 1);
  f.check(ex_put_truth_table(f.id(), type, n_blocks, static_cast<int>(vars.size()), table.data()),
          what);
}

void write_variables(const ExodusFile& f, const MeshData& d, const Blocks& b) {
  const std::vector<Variable> cell_vars = variables(d.cell_data);
  const std::vector<Variable> node_vars = variables(d.point_data);
  if (cell_vars.empty() && node_vars.empty()) return;
  declare_variables(f, EX_ELEM_BLOCK, cell_vars, static_cast<int>(b.used.size()));
  declare_variables(f, EX_NODAL, node_vars, 0);
  const double time = 0.0;
  f.check(ex_put_time(f.id(), 1, &time), "time step");
  std::vector<double> values;
  for (std::size_t k = 0; k < cell_vars.size(); ++k) {
    const Variable& v = cell_vars[k];
    const auto nc = static_cast<std::size_t>(v.array->n_components);
    std::size_t first = 0;
    for (int m : b.used) {
      const auto count = static_cast<std::size_t>(b.count[static_cast<std::size_t>(m)]);
      values.clear();
      for (std::size_t e = first; e < first + count; ++e)
        values.push_back(v.array->values[static_cast<std::size_t>(b.order[e]) * nc +
                                         static_cast<std::size_t>(v.component)]);
      f.check(ex_put_var(f.id(), 1, EX_ELEM_BLOCK, static_cast<int>(k) + 1, m + 1,
                         static_cast<int64_t>(count), values.data()),
              "element variable " + v.name);
      first += count;
    }
  }
  for (std::size_t k = 0; k < node_vars.size(); ++k) {
    const Variable& v = node_vars[k];
    const auto nc = static_cast<std::size_t>(v.array->n_components);
    values.clear();
    for (std::size_t p = 0; p < d.points.size(); ++p)
      values.push_back(v.array->values[p * nc + static_cast<std::size_t>(v.component)]);
    f.check(ex_put_var(f.id(), 1, EX_NODAL, static_cast<int>(k) + 1, 1,
                       static_cast<int64_t>(values.size()), values.data()),
            "nodal variable " + v.name);
  }
}

// Names longer than the Exodus default of 32 characters are kept whole: the file's name
// length is raised to the longest one (at most 255, netCDF's limit; longer ones are cut).
int longest_name(const MeshData& d, const Blocks& b, const detail::MeshSets& sets) {
  std::size_t n = 32;
  for (int m : b.used) n = std::max(n, b.names[static_cast<std::size_t>(m)].size());
  for (const auto& s : sets.side_sets) n = std::max(n, s.name.size());
  for (const auto& s : sets.node_sets) n = std::max(n, s.name.size());
  for (const auto* group : {&d.cell_data, &d.point_data})
    for (const DataArray& a : *group) n = std::max(n, a.name.size() + 2);
  return static_cast<int>(std::min<std::size_t>(n, 255));
}

void check_writable(const MeshData& d, const std::string& path) {
  if ((d.dim != 2 && d.dim != 3) || d.n_cells() == 0)
    throw OptionError(path + ": nothing to write: the data has no quad or hex cells");
  if (writes_directly(path))
    throw OptionError(path + ": an Exodus II file is written by seeking: give a regular file");
  const auto limit = static_cast<std::size_t>(std::numeric_limits<int>::max());
  if (d.points.size() >= limit || d.cells.size() >= limit)
    throw OptionError(path + ": too large for the 32-bit ids of this writer");
  d.check_array_sizes(path);
}

}  // namespace

void write_exodus(const MeshData& data, const std::string& path, const WriteOptions& options) {
  check_writable(data, path);
  const Blocks blocks = group_cells(data, path);
  const detail::MeshSets sets = detail::mesh_sets(data, blocks.material, blocks.names,
                                                  blocks.element_of_cell, options.exodus_sets);
  AtomicFile out(path);
  out.stream().close();
  ExodusFile f = ExodusFile::create(out.file_name(), path);
  const int name_length = longest_name(data, blocks, sets);
  if (name_length > 32) f.check(ex_set_max_name_length(f.id(), name_length), "name length");
  const std::string title = metadata_value(data, "hexadapt_tool", "hexadapt") + " mesh";
  f.check(ex_put_init(f.id(), title.c_str(), data.dim, data.n_points(), data.n_cells(),
                      static_cast<int64_t>(blocks.used.size()),
                      static_cast<int64_t>(sets.node_sets.size()),
                      static_cast<int64_t>(sets.side_sets.size())),
          "initialization");
  write_blocks(f, data, blocks);
  write_coordinates(f, data);
  write_maps(f, data, blocks);
  write_sets(f, sets);
  write_records(f, data);
  write_variables(f, data, blocks);
  f.close();
  out.commit();
}

}  // namespace hexadapt::io
