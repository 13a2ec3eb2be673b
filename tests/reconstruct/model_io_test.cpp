#include <OpenMesh/Core/IO/MeshIO.hh>

#include "hexadapt/reconstruct/model_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hexadapt/core/error.h"
#include "hexadapt/reconstruct/reconstruct.h"
#include "reconstruct/cases.h"

namespace hexadapt::reconstruct {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("hexadapt_model_io_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ModelIo, VtkPolyDataCountsMatchTheModel) {
  const auto c = testcase::five_by_five();
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, ReconstructOptions{});
  const fs::path path = temp_dir("vtk") / "m.vtk";
  write_model_vtk(r.model, {"a", "b", "c"}, path.string());
  const std::string text = slurp(path);
  EXPECT_NE(text.find("DATASET POLYDATA"), std::string::npos);
  EXPECT_NE(text.find("POINTS " + std::to_string(r.model.points.size()) + " double"), std::string::npos);
  EXPECT_NE(text.find("LINES " + std::to_string(r.model.facets.size())), std::string::npos);
  EXPECT_NE(text.find("VERTICES " + std::to_string(r.model.corners.size())), std::string::npos);
  EXPECT_NE(text.find("CELL_DATA " + std::to_string(r.model.facets.size() + r.model.corners.size())),
            std::string::npos);
  EXPECT_THROW(write_model_openmesh(r.model, {"a", "b", "c"}, (path.parent_path() / "m").string()),
               OptionError);
}

TEST(ModelIo, OpenMeshPatchesRoundTrip) {
  const auto c = testcase::sphere(6, 2.2);
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, ReconstructOptions{});
  const auto patches = model_patches(r.model);
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_EQ(patches[0].mesh.n_faces(), r.model.facets.size());
  const fs::path dir = temp_dir("om");
  const auto paths = write_model_openmesh(r.model, {"out", "in"}, (dir / "m").string());
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(fs::path(paths[0]).filename(), "m.out-in.om");
  OmPolyMesh back;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(back, paths[0]));
  EXPECT_EQ(back.n_faces(), r.model.facets.size());
  // A closed surface: no boundary halfedges unless a non-manifold spot was split.
  std::size_t boundary = 0;
  for (auto h : back.halfedges()) boundary += back.is_boundary(h);
  EXPECT_EQ(boundary, 0u);
}

}  // namespace
}  // namespace hexadapt::reconstruct
