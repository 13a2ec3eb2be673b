// What the ranks merging a .pvtu's pieces (vtk_collection_merge.cpp) agree on before the
// merge: the first piece, which every piece must match, and the errors of those checks.
#include <cstdint>

#include "hexadapt/core/error.h"
#include "vtk_collection.h"

namespace hexadapt::io::detail {

namespace {

void put_string(dist::Buffer& b, const std::string& s) {
  b.put_vector(std::vector<char>(s.begin(), s.end()));
}

std::string get_string(dist::Buffer& b) {
  const std::vector<char> v = b.get_vector<char>();
  return {v.begin(), v.end()};
}

void put_arrays(dist::Buffer& b, const std::vector<DataArray>& arrays) {
  b.put(static_cast<std::uint64_t>(arrays.size()));
  for (const DataArray& a : arrays) {
    put_string(b, a.name);
    b.put(a.n_components);
    b.put(a.type);
  }
}

std::vector<DataArray> get_arrays(dist::Buffer& b) {
  std::vector<DataArray> arrays(b.get<std::uint64_t>());
  for (DataArray& a : arrays) {
    a.name = get_string(b);
    a.n_components = b.get<int>();
    a.type = b.get<ScalarType>();
  }
  return arrays;
}

dist::Buffer header_of(const NamedMesh& m) {
  dist::Buffer b;
  put_string(b, m.file);
  b.put(m.data.dim);
  b.put(static_cast<std::uint64_t>(m.data.metadata.size()));
  for (const auto& [key, value] : m.data.metadata) {
    put_string(b, key);
    put_string(b, value);
  }
  put_arrays(b, m.data.cell_data);
  put_arrays(b, m.data.point_data);
  return b;
}

NamedMesh read_header(dist::Buffer& b) {
  NamedMesh m;
  m.file = get_string(b);
  m.data.dim = b.get<int>();
  m.data.metadata.resize(b.get<std::uint64_t>());
  for (auto& [key, value] : m.data.metadata) {
    key = get_string(b);
    value = get_string(b);
  }
  m.data.cell_data = get_arrays(b);
  m.data.point_data = get_arrays(b);
  return m;
}

}  // namespace

NamedMesh first_piece_header(const dist::Communicator& comm, const std::vector<NamedMesh>& pieces,
                             const std::string& file) {
  dist::Buffer mine;
  if (!pieces.empty()) mine = header_of(pieces.front());
  for (dist::Buffer& b : dist::all_gather(comm, mine))
    if (!b.bytes().empty()) return read_header(b);
  throw InputError(file, "pieces", "no piece with cells");
}

void agree_on_input_errors(const dist::Communicator& comm, const std::function<void()>& f) {
  if (comm.size() == 1) return f();
  dist::Buffer mine;
  try {
    f();
  } catch (const InputError& e) {
    put_string(mine, e.file());
    put_string(mine, e.where());
    put_string(mine, e.message());
  }
  for (dist::Buffer& b : dist::all_gather(comm, mine))
    if (!b.bytes().empty()) {
      std::string file = get_string(b), where = get_string(b);
      throw InputError(std::move(file), std::move(where), get_string(b));
    }
}

}  // namespace hexadapt::io::detail
