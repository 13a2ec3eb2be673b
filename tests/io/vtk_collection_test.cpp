// The collection reader (vtk_collection.h) on small hand-written files served from memory:
// pieces merged and welded, ghost and repeated cells, structured tiling, time steps, and the
// refusals (missing piece, foreign piece, escaping names, lying extents, mixed kinds).
#include "hexadapt/io/vtk_collection.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/io/vtk_xml.h"

namespace hexadapt::io {
namespace {

using Files = std::map<std::string, std::string>;

FileLoader loader(const Files& files) {
  return [&files](const std::string& path) {
    const auto it = files.find(path);
    if (it == files.end()) throw IoError(path + ": cannot open: No such file or directory");
    return it->second;
  };
}

// One unit quad at x0 (x from x0 to x0 + 1, y from 0 to 1) with vf_a = a, as a .vtu.
std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// One quad from x0 to x0 + 1, y from 0 to 1, all coordinates times `scale`, with vf_a = a.
std::string quad_vtu(double x0, double a, const std::string& extra_cell_array = "",
                     double scale = 1) {
  const std::string x = number(x0 * scale), x1 = number((x0 + 1) * scale), y = number(scale);
  return R"(<VTKFile type="UnstructuredGrid" version="1.0"><UnstructuredGrid>
<Piece NumberOfPoints="4" NumberOfCells="1"><Points>
<DataArray type="Float64" NumberOfComponents="3" format="ascii">)" +
         x + " 0 0 " + x1 + " 0 0 " + x1 + " " + y + " 0 " + x + " " + y +
         R"( 0</DataArray></Points>
<Cells><DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">9</DataArray></Cells>
<CellData><DataArray type="Float64" Name="vf_a" format="ascii">)" +
         std::to_string(a) + "</DataArray>" + extra_cell_array +
         "</CellData></Piece></UnstructuredGrid></VTKFile>";
}

std::string pvtu(const std::vector<std::string>& sources) {
  std::string s =
      R"(<VTKFile type="PUnstructuredGrid" version="1.0"><PUnstructuredGrid GhostLevel="0">
<PCellData><PDataArray type="Float64" Name="vf_a"/></PCellData>
<PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>)";
  for (const auto& src : sources) s += "<Piece Source=\"" + src + "\"/>";
  return s + "</PUnstructuredGrid></VTKFile>";
}

MeshData read(const Files& files, const std::string& name, const ReadOptions& options = {}) {
  return read_vtk_collection(files.at(name), name, options, loader(files));
}

TEST(VtkCollection, PvtuMergesPiecesAndWeldsTheirCommonPoints) {
  const Files files{{"d/two.pvtu", pvtu({"p0.vtu", "sub/p1.vtu"})},
                    {"d/p0.vtu", quad_vtu(0, 1)},
                    {"d/sub/p1.vtu", quad_vtu(1, 0.25)}};
  const MeshData d = read(files, "d/two.pvtu");
  EXPECT_EQ(d.dim, 2);
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.n_points(), 6);
  EXPECT_EQ(d.find_cell_array("vf_a")->values, (std::vector<double>{1, 0.25}));
  // The right quad uses the left one's x = 1 points.
  EXPECT_EQ(d.cells[4], d.cells[1]);
  EXPECT_EQ(d.cells[7], d.cells[2]);
}

TEST(VtkCollection, WeldingToleranceIsRelativeToTheCellSize) {
  Files files{{"two.pvtu", pvtu({"p0.vtu", "p1.vtu"})}, {"p0.vtu", quad_vtu(0, 1)}};
  files["p1.vtu"] = quad_vtu(1 + 1e-9, 0);  // x from 1 + 1e-9 to 2 + 1e-9
  EXPECT_EQ(read(files, "two.pvtu").n_points(), 6);
  files["p1.vtu"] = quad_vtu(1 + 1e-3, 0);
  EXPECT_EQ(read(files, "two.pvtu").n_points(), 8);
  ReadOptions coarse;
  coarse.weld_tolerance = 1e-2;
  EXPECT_EQ(read(files, "two.pvtu", coarse).n_points(), 6);
}

TEST(VtkCollection, TheSameWeldingAtAnyUnit) {
  for (const double scale : {1e-12, 1.0, 1e9}) {
    SCOPED_TRACE(scale);
    Files files{{"two.pvtu", pvtu({"p0.vtu", "p1.vtu"})}, {"p0.vtu", quad_vtu(0, 1, "", scale)}};
    files["p1.vtu"] = quad_vtu(1 + 1e-9, 0, "", scale);
    EXPECT_EQ(read(files, "two.pvtu").n_points(), 6);
    files["p1.vtu"] = quad_vtu(1 + 1e-3, 0, "", scale);
    EXPECT_EQ(read(files, "two.pvtu").n_points(), 8);
  }
}

TEST(VtkCollection, GhostCellsAreDroppedAndRepeatedCellsKeptOnce) {
  const std::string ghost =
      R"(<DataArray type="UInt8" Name="vtkGhostType" format="ascii">1</DataArray>)";
  const std::string owned =
      R"(<DataArray type="UInt8" Name="vtkGhostType" format="ascii">0</DataArray>)";
  Files files{{"g.pvtu", pvtu({"a.vtu", "b.vtu", "c.vtu"})},
              {"a.vtu", quad_vtu(0, 1, owned)},
              {"b.vtu", quad_vtu(0, 1, ghost)},  // a's cell again, as b's ghost
              {"c.vtu", quad_vtu(1, 0, owned)}};
  MeshData d = read(files, "g.pvtu");
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.n_points(), 6);
  EXPECT_EQ(d.find_cell_array("vtkGhostType"), nullptr);
  // VTK's writer gives every piece the whole mesh when its source cannot split it.
  files = {{"same.pvtu", pvtu({"a.vtu", "a.vtu", "a.vtu", "a.vtu"})}, {"a.vtu", quad_vtu(0, 1)}};
  d = read(files, "same.pvtu");
  EXPECT_EQ(d.n_cells(), 1);
  EXPECT_EQ(d.n_points(), 4);
}

TEST(VtkCollection, AMissingPieceIsAnIoErrorNamingIt) {
  const Files files{{"two.pvtu", pvtu({"p0.vtu", "gone_3.vtu"})}, {"p0.vtu", quad_vtu(0, 1)}};
  try {
    read(files, "two.pvtu");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("gone_3.vtu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("two.pvtu"), std::string::npos) << e.what();
  }
}

TEST(VtkCollection, NamesOutsideTheFolderAreRefused) {
  for (const std::string bad : {"/etc/p.vtu", "../p.vtu", "a/../../p.vtu", ""}) {
    SCOPED_TRACE(bad);
    const Files files{{"d/x.pvtu", pvtu({bad})}};
    EXPECT_THROW(read(files, "d/x.pvtu"), InputError);
  }
}

const std::string image_vti = R"(<VTKFile type="ImageData" version="1.0">
<ImageData WholeExtent="0 1 0 1 0 0" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="0 1 0 1 0 0">
<CellData><DataArray type="Float64" Name="vf_a" format="ascii">1</DataArray></CellData>
</Piece></ImageData></VTKFile>)";

std::string hex_vtu() {
  return R"(<VTKFile type="UnstructuredGrid" version="1.0"><UnstructuredGrid>
<Piece NumberOfPoints="8" NumberOfCells="1"><Points>
<DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</DataArray></Points>
<Cells><DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 4 5 6 7</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">8</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">11</DataArray></Cells>
<CellData><DataArray type="Float64" Name="vf_a" format="ascii">1</DataArray></CellData>
</Piece></UnstructuredGrid></VTKFile>)";
}

void expect_input_error(const Files& files, const std::string& name, const std::string& text) {
  try {
    read(files, name);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), name);
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(VtkCollection, APieceOfAnotherKindIsRefused) {
  expect_input_error({{"x.pvtu", pvtu({"a.vti"})}, {"a.vti", image_vti}}, "x.pvtu",
                     "expected an UnstructuredGrid");
}

std::string vtm(const std::vector<std::string>& files) {
  std::string s = R"(<VTKFile type="vtkMultiBlockDataSet" version="1.0"><vtkMultiBlockDataSet>)";
  int k = 0;
  for (const auto& f : files)
    s += "<Block index=\"" + std::to_string(k) + "\"><DataSet index=\"0\" file=\"" + f +
         "\"/></Block>";
  return s + "<DataSet index=\"9\"/></vtkMultiBlockDataSet></VTKFile>";
}

TEST(VtkCollection, MultiBlockMergesBlocksOfOneKindOnly) {
  Files files{{"m.vtm", vtm({"a.vti", "b.vtu"})}, {"a.vti", image_vti}, {"b.vtu", quad_vtu(1, 0)}};
  const MeshData d = read(files, "m.vtm");
  EXPECT_EQ(d.n_cells(), 2);
  EXPECT_EQ(d.n_points(), 6);
  files["b.vtu"] = hex_vtu();
  expect_input_error(files, "m.vtm", "one kind of cell");
  files["m.vtm"] = vtm({"m.vtm"});
  expect_input_error(files, "m.vtm", "nested");
  files["c.vtp"] = R"(<VTKFile type="PolyData" version="1.0"><PolyData/></VTKFile>)";
  files["m.vtm"] = vtm({"c.vtp"});
  expect_input_error(files, "m.vtm", "not a grid of quads or hexes");
}

std::string pvd() {
  return R"(<VTKFile type="Collection" version="0.1"><Collection>
<DataSet timestep="1" part="0" file="t2.vtu"/>
<DataSet timestep="0" part="0" file="t0.vtu"/>
<DataSet timestep="0.5" part="0" file="t1.vtu"/>
</Collection></VTKFile>)";
}

TEST(VtkCollection, TimeSeriesPicksTheRequestedStep) {
  const Files files{{"s.pvd", pvd()},
                    {"t0.vtu", quad_vtu(0, 0)},
                    {"t1.vtu", quad_vtu(0, 0.5)},
                    {"t2.vtu", quad_vtu(0, 1)}};
  ReadOptions o;
  o.step = 1;
  EXPECT_EQ(read(files, "s.pvd", o).find_cell_array("vf_a")->values[0], 0.5);
  o.step.reset();
  o.time = 1.0000000001;
  EXPECT_EQ(read(files, "s.pvd", o).find_cell_array("vf_a")->values[0], 1);
  o.time = 0;
  EXPECT_EQ(read(files, "s.pvd", o).find_cell_array("vf_a")->values[0], 0);
}

TEST(VtkCollection, AnUnknownOrMissingStepListsTheTimes) {
  const Files files{{"s.pvd", pvd()},
                    {"t0.vtu", quad_vtu(0, 0)},
                    {"t1.vtu", quad_vtu(0, 0.5)},
                    {"t2.vtu", quad_vtu(0, 1)}};
  const std::string listed = "3 steps: 0: t = 0, 1: t = 0.5, 2: t = 1";
  expect_input_error(files, "s.pvd", listed);
  ReadOptions o;
  o.step = 3;
  try {
    read(files, "s.pvd", o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("no time step 3"), std::string::npos) << e.what();
    EXPECT_NE(e.message().find(listed), std::string::npos) << e.what();
  }
  o.step.reset();
  o.time = 0.7;
  try {
    read(files, "s.pvd", o);
    FAIL();
  } catch (const InputError& e) {
    // The wording of every time series, Exodus too (Exodus.ReadsTheChosenTimeStep).
    EXPECT_NE(e.message().find("no time step at t = 0.7; the series holds " + listed),
              std::string::npos)
        << e.what();
  }
  o.step = 0;
  EXPECT_THROW(read(files, "s.pvd", o), OptionError);
}

// A 2 x 1 x 1 rectilinear grid of hexes with vf_a = 0.25, 0.75, whole or in pieces.
std::string vtr(const std::string& extent, const std::string& x, const std::string& vf) {
  return R"(<VTKFile type="RectilinearGrid" version="1.0"><RectilinearGrid WholeExtent=")" +
         extent + R"("><Piece Extent=")" + extent + R"(">
<CellData><DataArray type="Float64" Name="vf_a" format="ascii">)" +
         vf + R"(</DataArray></CellData><Coordinates>
<DataArray type="Float64" format="ascii">)" +
         x + R"(</DataArray><DataArray type="Float64" format="ascii">0 1</DataArray>
<DataArray type="Float64" format="ascii">0 2</DataArray></Coordinates>
</Piece></RectilinearGrid></VTKFile>)";
}

std::string pvtr(const std::string& whole,
                 const std::vector<std::pair<std::string, std::string>>& pieces) {
  std::string s =
      R"(<VTKFile type="PRectilinearGrid" version="1.0"><PRectilinearGrid WholeExtent=")" + whole +
      R"(" GhostLevel="0">)";
  for (const auto& [extent, src] : pieces)
    s += "<Piece Extent=\"" + extent + "\" Source=\"" + src + "\"/>";
  return s + "</PRectilinearGrid></VTKFile>";
}

TEST(VtkCollection, StructuredPiecesBecomeTheOneGrid) {
  const MeshData single = read_vtk_xml(vtr("0 2 0 1 0 1", "0 1 3", "0.25 0.75"), "one.vtr");
  const Files files{
      {"p.pvtr", pvtr("0 2 0 1 0 1", {{"1 2 0 1 0 1", "b.vtr"}, {"0 1 0 1 0 1", "a.vtr"}})},
      {"a.vtr", vtr("0 1 0 1 0 1", "0 1", "0.25")},
      {"b.vtr", vtr("1 2 0 1 0 1", "1 3", "0.75")}};
  const MeshData d = read(files, "p.pvtr");
  EXPECT_EQ(d.points, single.points);
  EXPECT_EQ(d.cells, single.cells);
  EXPECT_EQ(d.structured_cells, single.structured_cells);
  EXPECT_EQ(d.find_cell_array("vf_a")->values, single.find_cell_array("vf_a")->values);
}

TEST(VtkCollection, StructuredPiecesThatLieAreRefused) {
  Files files{{"a.vtr", vtr("0 1 0 1 0 1", "0 1", "0.25")},
              {"b.vtr", vtr("1 2 0 1 0 1", "1 3", "0.75")}};
  files["p.pvtr"] = pvtr("0 2 0 1 0 1", {{"0 1 0 1 0 1", "a.vtr"}});
  expect_input_error(files, "p.pvtr", "the pieces hold only 1");
  files["p.pvtr"] = pvtr("0 2000000000 0 2000000000 0 1", {{"0 1 0 1 0 1", "a.vtr"}});
  expect_input_error(files, "p.pvtr", "too many points");
  files["p.pvtr"] = pvtr("0 2 0 1 0 1", {{"0 1 0 1 0 1", "a.vtr"}, {"0 2 0 1 0 1", "b.vtr"}});
  expect_input_error(files, "p.pvtr", "but the piece");
  files["p.pvtr"] = pvtr("0 1 0 1 0 1", {{"0 1 0 1 0 1", "a.vtr"}, {"1 2 0 1 0 1", "b.vtr"}});
  expect_input_error(files, "p.pvtr", "not inside the WholeExtent");
  files["p.pvtr"] =
      pvtr("0 3 0 1 0 1",
           {{"0 1 0 1 0 1", "a.vtr"}, {"0 1 0 1 0 1", "a.vtr"}, {"1 2 0 1 0 1", "b.vtr"}});
  expect_input_error(files, "p.pvtr", "cell (2, 0, 0) of the whole extent is in no piece");
  files["c.vtr"] = vtr("1 2 0 1 0 1", "1.5 3", "0.75");
  files["p.pvtr"] = pvtr("0 2 0 1 0 1", {{"0 1 0 1 0 1", "a.vtr"}, {"1 2 0 1 0 1", "c.vtr"}});
  expect_input_error(files, "p.pvtr", "not where the other pieces put");
  files["p.pvtr"] = pvtr("0 2 0 1 0 1", {{"0 1 0 1 0 1", "a.vtr"}, {"1 2 0 1 0 1", "a.vti"}});
  files["a.vti"] = image_vti;
  expect_input_error(files, "p.pvtr", "expected a RectilinearGrid");
}

}  // namespace
}  // namespace hexadapt::io
