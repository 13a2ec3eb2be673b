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

void expect_same_model(const InterfaceModel& a, const InterfaceModel& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.points, b.points);  // 17 digits: exact
  EXPECT_EQ(a.facets, b.facets);
  EXPECT_EQ(a.facet_materials, b.facet_materials);
  EXPECT_EQ(a.curves, b.curves);
  EXPECT_EQ(a.corners, b.corners);
}

TEST(ModelIo, VtkReadsBackWhatItWrote) {
  const auto c2 = testcase::five_by_five();
  const auto r2 = reconstruct(c2.mesh, c2.fractions, c2.majority, ReconstructOptions{});
  const fs::path dir = temp_dir("read");
  write_model_vtk(r2.model, {"a", "b", "c"}, (dir / "2d.vtk").string());
  const ModelFile f2 = read_model_vtk((dir / "2d.vtk").string());
  EXPECT_EQ(f2.materials, (std::vector<std::string>{"a", "b", "c"}));
  expect_same_model(f2.model, r2.model);

  // Three materials reaching the domain boundary: facets, curves and corners.
  const auto c3 = testcase::make_case(make_hex_grid(5, 5, 5), 3, [](const Vec3& p) {
    return p.x() < 2.3 ? 0 : p.y() < 2.7 ? 1 : 2;
  });
  const auto r3 = reconstruct(c3.mesh, c3.fractions, c3.majority, ReconstructOptions{});
  ASSERT_FALSE(r3.model.curves.empty());
  ASSERT_FALSE(r3.model.corners.empty());
  write_model_vtk(r3.model, {"x", "y", "z"}, (dir / "3d.vtk").string());
  const ModelFile f3 = read_model_vtk((dir / "3d.vtk").string());
  EXPECT_EQ(f3.materials, (std::vector<std::string>{"x", "y", "z"}));
  expect_same_model(f3.model, r3.model);
}

// Names with spaces, commas, '%' and a tab come back as they were: the title line separates
// names with spaces (they came back split, and adapt then found the model's materials not
// the grid's).
TEST(ModelIo, NamesWithSpacesAndCommasRoundTrip) {
  const auto c = testcase::five_by_five();
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, ReconstructOptions{});
  const fs::path dir = temp_dir("names");
  const std::vector<std::string> names = {"Body, Nose", "50% air", "a\tb"};
  write_model_vtk(r.model, names, (dir / "m.vtk").string());
  EXPECT_EQ(read_model_vtk((dir / "m.vtk").string()).materials, names);
}

TEST(ModelIo, VtkReaderNamesTheFileAndLine) {
  const auto c = testcase::sphere(5, 1.8);
  const auto r = reconstruct(c.mesh, c.fractions, c.majority, ReconstructOptions{});
  const fs::path dir = temp_dir("bad");
  const fs::path path = dir / "m.vtk";
  write_model_vtk(r.model, {"out", "in"}, path.string());
  const std::string text = slurp(path);
  auto expect_error = [&](const std::string& content, const std::string& part) {
    std::ofstream(path, std::ios::binary) << content;
    try {
      read_model_vtk(path.string());
      ADD_FAILURE() << "no error for " << part;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  expect_error(text.substr(0, text.size() / 2), "line");
  std::string other = text;
  other.replace(other.find("hexadapt interface model"), 8, "someone ");
  expect_error(other, "line 2");
  std::string bad_id = text;
  bad_id.replace(bad_id.find("\n4 ", bad_id.find("POLYGONS")) + 3, 1, "99999999 ");
  expect_error(bad_id, "line");
  EXPECT_THROW(read_model_vtk((dir / "missing.vtk").string()), IoError);
}

}  // namespace
}  // namespace hexadapt::reconstruct
