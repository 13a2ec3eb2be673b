// MeshIO.hh registers OpenMesh's readers and writers; it goes before the mesh kernel.
#include <OpenMesh/Core/IO/MeshIO.hh>

#include "hexadapt/reconstruct/model_io.h"

#include <iostream>
#include <map>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/io/atomic_file.h"
#include "model_title.h"

namespace hexadapt::reconstruct {

namespace {

// A material's name in a file name: '/' (and control bytes) would leave the folder.
std::string name_of(const std::vector<std::string>& names, int m) {
  std::string n = m >= 0 && static_cast<std::size_t>(m) < names.size()
                      ? names[static_cast<std::size_t>(m)]
                      : std::to_string(m);
  for (char& c : n)
    if (c == '/' || static_cast<unsigned char>(c) < ' ') c = '_';
  return n;
}

// OpenMesh talks on its own streams (omerr for faces it cannot add, omout) and on std::clog
// (its .om writer's "#bytes written"); the library never prints, so they are muted while we
// call it.
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : err_(omerr().is_enabled()), log_(omlog().is_enabled()), out_(omout().is_enabled()),
        clog_(std::clog.rdbuf(nullptr)) {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    if (err_) omerr().enable();
    if (log_) omlog().enable();
    if (out_) omout().enable();
    std::clog.rdbuf(clog_);
    std::clog.clear();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  bool err_, log_, out_;
  std::streambuf* clog_;
};

}  // namespace

void write_model_vtk(const InterfaceModel& model, const std::vector<std::string>& materials,
                     const std::string& path) {
  std::ostringstream s;
  s.precision(17);
  s << "# vtk DataFile Version 3.0\nhexadapt interface model; materials:";
  for (const auto& n : materials) s << ' ' << detail::title_name(n);
  s << "\nASCII\nDATASET POLYDATA\nPOINTS " << model.points.size() << " double\n";
  for (const Vec3& p : model.points) s << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  const std::size_t nf = model.facets.size(), nc = model.curves.size(), nv = model.corners.size();
  const bool flat = model.dim == 2;
  if (nv) {
    s << "VERTICES " << nv << ' ' << 2 * nv << '\n';
    for (index_t v : model.corners) s << "1 " << v << '\n';
  }
  const std::size_t n_lines = nc + (flat ? nf : 0);
  if (n_lines) {
    s << "LINES " << n_lines << ' ' << 3 * n_lines << '\n';
    for (const auto& e : model.curves) s << "2 " << e[0] << ' ' << e[1] << '\n';
    if (flat)
      for (const auto& f : model.facets) s << "2 " << f[0] << ' ' << f[1] << '\n';
  }
  if (!flat && nf) {
    s << "POLYGONS " << nf << ' ' << 5 * nf << '\n';
    for (const auto& f : model.facets) s << "4 " << f[0] << ' ' << f[1] << ' ' << f[2] << ' ' << f[3] << '\n';
  }
  // Cell order in POLYDATA: vertices, lines, polygons.
  const std::size_t n_cells = nv + nc + nf;
  s << "CELL_DATA " << n_cells << '\n';
  // A FIELD block: every reader (VTK's without ReadAllScalars too) loads all its arrays.
  auto write_array = [&](const char* name, int feature_value, int which) {
    s << name << " 1 " << n_cells << " int\n";
    for (std::size_t i = 0; i < nv; ++i) s << (which == 2 ? 2 : feature_value) << '\n';
    for (std::size_t i = 0; i < nc; ++i) s << (which == 2 ? 1 : feature_value) << '\n';
    for (const auto& m : model.facet_materials) s << (which == 2 ? 0 : m[static_cast<std::size_t>(which)]) << '\n';
  };
  if (n_cells) {
    s << "FIELD FieldData 3\n";
    write_array("material_lo", -1, 0);
    write_array("material_hi", -1, 1);
    write_array("kind", 0, 2);
  }
  io::write_file_atomically(path, s.str());
}

std::vector<ModelPatch> model_patches(const InterfaceModel& model) {
  if (model.dim != 3) throw OptionError("OpenMesh surfaces exist for 3D models only");
  std::map<std::pair<int, int>, std::vector<std::size_t>> by_pair;
  for (std::size_t f = 0; f < model.facets.size(); ++f)
    by_pair[{model.facet_materials[f][0], model.facet_materials[f][1]}].push_back(f);
  std::vector<ModelPatch> patches;
  // Faces OpenMesh cannot add (non-manifold spots) get their own vertex copies.
  const QuietOpenMesh quiet;
  for (const auto& [pair, facets] : by_pair) {
    ModelPatch patch;
    patch.lo = pair.first;
    patch.hi = pair.second;
    std::map<index_t, OmPolyMesh::VertexHandle> handle;
    auto point = [&](index_t v) {
      const Vec3& p = model.points[static_cast<std::size_t>(v)];
      return OmPolyMesh::Point(p.x(), p.y(), p.z());
    };
    for (std::size_t f : facets) {
      std::vector<OmPolyMesh::VertexHandle> vh;
      for (index_t v : model.facets[f]) {
        auto it = handle.find(v);
        if (it == handle.end()) it = handle.emplace(v, patch.mesh.add_vertex(point(v))).first;
        vh.push_back(it->second);
      }
      if (!patch.mesh.add_face(vh).is_valid()) {
        for (std::size_t i = 0; i < vh.size(); ++i) vh[i] = patch.mesh.add_vertex(point(model.facets[f][i]));
        patch.mesh.add_face(vh);
      }
    }
    patches.push_back(std::move(patch));
  }
  return patches;
}

std::vector<std::string> write_model_openmesh(const InterfaceModel& model,
                                              const std::vector<std::string>& materials,
                                              const std::string& stem, const std::string& ext) {
  if (ext != "om" && ext != "obj") throw OptionError("OpenMesh model format must be om or obj");
  std::vector<std::string> paths;
  const QuietOpenMesh quiet;
  for (const ModelPatch& p : model_patches(model)) {
    const std::string path = stem + "." + name_of(materials, p.lo) + "-" + name_of(materials, p.hi) + "." + ext;
    io::AtomicFile out(path);
    if (!OpenMesh::IO::write_mesh(p.mesh, out.stream(), "." + ext,
                                  ext == "om" ? OpenMesh::IO::Options::Binary
                                              : OpenMesh::IO::Options::Default,
                                  17))
      throw IoError(path + ": OpenMesh could not write the surface");
    out.commit();
    paths.push_back(path);
  }
  return paths;
}

}  // namespace hexadapt::reconstruct
