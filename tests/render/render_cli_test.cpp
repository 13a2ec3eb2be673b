// hexadapt-render end to end: meshes written by the library, the built tool run on them,
// the PNG's size read from its header and its pixels decoded with cairo.
#ifdef HEXADAPT_HAVE_RENDER
#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<int, 3>;

// The first two colours of the tool's categorical palette.
constexpr Rgb blue{0x1f, 0x77, 0xb4};
constexpr Rgb orange{0xff, 0x7f, 0x0e};

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hexadapt-render-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  int run(const std::string& args) const {
    const std::string cmd = std::string(HEXADAPT_TOOLS_DIR) + "/hexadapt-render " + args + " > " +
                            path("stdout.txt") + " 2> " + path("stderr.txt");
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
};

// Width and height from the IHDR chunk: bytes 16..23, big-endian.
std::array<std::uint32_t, 2> png_size(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<unsigned char> b(24);
  in.read(reinterpret_cast<char*>(b.data()), 24);
  EXPECT_TRUE(in) << file;
  EXPECT_EQ(b[1], 'P');
  EXPECT_EQ(b[12], 'I');
  auto be = [&](int at) {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v = (v << 8) | b[static_cast<std::size_t>(at + k)];
    return v;
  };
  return {be(16), be(20)};
}

// The pixels of one row, decoded with cairo.
std::vector<Rgb> png_row(const std::string& file, int y) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(file.c_str());
  EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  std::vector<Rgb> row;
  const int w = cairo_image_surface_get_width(s), stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  for (int x = 0; x < w; ++x) {
    std::uint32_t px = 0;
    std::memcpy(&px, data + y * stride + 4 * x, 4);
    row.push_back({static_cast<int>((px >> 16) & 0xff), static_cast<int>((px >> 8) & 0xff),
                   static_cast<int>(px & 0xff)});
  }
  cairo_surface_destroy(s);
  return row;
}

// All pixels, decoded with cairo: at(x, y).
struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;
  const Rgb& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
};

Image png_image(const std::string& file) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(file.c_str());
  EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  Image im;
  im.width = cairo_image_surface_get_width(s);
  im.height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      std::uint32_t px = 0;
      std::memcpy(&px, data + y * stride + 4 * x, 4);
      im.pixels.push_back({static_cast<int>((px >> 16) & 0xff), static_cast<int>((px >> 8) & 0xff),
                           static_cast<int>(px & 0xff)});
    }
  cairo_surface_destroy(s);
  return im;
}

bool near(const Rgb& a, const Rgb& b, int tolerance) {
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(a[k] - b[k]) > tolerance) return false;
  return true;
}

int first(const std::vector<Rgb>& row, const Rgb& c) {
  for (std::size_t x = 0; x < row.size(); ++x)
    if (row[x] == c) return static_cast<int>(x);
  return -1;
}
int count(const std::vector<Rgb>& row, const Rgb& c) {
  int n = 0;
  for (const Rgb& p : row) n += p == c;
  return n;
}

io::DataArray cell_array(const std::string& name, std::vector<double> values) {
  io::DataArray a;
  a.name = name;
  a.values = std::move(values);
  return a;
}

// 4 x 2 quads on [0,4] x [0,2]: material "left" for x < 2, "right" for x > 2.
io::MeshData two_materials_2d() {
  io::MeshData d = io::from_mesh(make_quad_grid(4, 2));
  std::vector<double> m, left, right;
  for (index_t c = 0; c < d.n_cells(); ++c) {
    const double x = d.points[d.cells[static_cast<std::size_t>(4 * c)].idx()].x();
    const bool is_left = x < 1.5;
    m.push_back(is_left ? 0 : 1);
    left.push_back(is_left ? 1 : 0);
    right.push_back(is_left ? 0 : 1);
  }
  d.set_cell_array(cell_array("vf_left", left));
  d.set_cell_array(cell_array("vf_right", right));
  d.set_cell_array(cell_array("material", m));
  return d;
}

TEST_F(RenderCli, TwoMaterialsIn2D) {
  io::write_mesh(two_materials_2d(), path("mesh.vtu"));
  ASSERT_EQ(run(path("mesh.vtu") + " -o " + path("mesh.png") + " --size 500x220 --no-edges" +
                " --json " + path("report.json")),
            0);
  ASSERT_TRUE(fs::exists(path("mesh.png")));
  const auto size = png_size(path("mesh.png"));
  EXPECT_EQ(size[0], 500u);
  EXPECT_EQ(size[1], 220u);
  // Through the middle of the plot, the left material comes first, then the right one, with
  // about as many pixels each; the legend squares add a few pixels on other rows only.
  const auto row = png_row(path("mesh.png"), 130);
  const int b = first(row, blue), o = first(row, orange);
  ASSERT_GE(b, 0);
  ASSERT_GE(o, 0);
  EXPECT_LT(b, o);
  EXPECT_NEAR(count(row, blue), count(row, orange), 4);
  EXPECT_GT(count(row, blue), 50);
}

TEST_F(RenderCli, SliceOf3DPicksTheLayer) {
  // 2 x 2 x 2 hexes: material 0 below z = 1, material 1 above.
  io::MeshData d = io::from_mesh(make_hex_grid(2, 2, 2));
  std::vector<double> m;
  for (index_t c = 0; c < d.n_cells(); ++c) {
    const double z = d.points[d.cells[static_cast<std::size_t>(8 * c)].idx()].z();
    m.push_back(z < 0.5 ? 0 : 1);
  }
  d.set_cell_array(cell_array("material", m));
  io::write_mesh(d, path("cube.vtu"));
  ASSERT_EQ(run(path("cube.vtu") + " -o " + path("low.png") + " --z 0.5 --size 300x200 --no-edges"),
            0);
  ASSERT_EQ(
      run(path("cube.vtu") + " -o " + path("high.png") + " --z 1.5 --size 300x200 --no-edges"), 0);
  const auto low = png_row(path("low.png"), 110), high = png_row(path("high.png"), 110);
  EXPECT_GT(count(low, blue), 50);
  EXPECT_EQ(count(low, orange), 0);
  EXPECT_GT(count(high, orange), 50);
  EXPECT_EQ(count(high, blue), 0);
}

TEST_F(RenderCli, QualityFieldAndErrors) {
  io::write_mesh(two_materials_2d(), path("mesh.vtu"));
  EXPECT_EQ(run(path("mesh.vtu") + " -o " + path("q.png") + " --color quality --size 400x300"), 0);
  EXPECT_EQ(png_size(path("q.png"))[0], 400u);
  EXPECT_EQ(run(path("mesh.vtu") + " -o " + path("x.png") + " --color no_such_array"), 1);
  EXPECT_EQ(run(path("mesh.vtu") + " -o " + path("x.png") + " --size 12"), 1);
  EXPECT_EQ(run(path("missing.vtu") + " -o " + path("x.png")), 2);
  EXPECT_FALSE(fs::exists(path("x.png")));
}

nlohmann::json read_json(const std::string& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// The quad grid of two_materials_2d with node (1, 1) pulled to (1.45, 1.3): four cells of
// lower quality, none inverted.
io::MeshData sheared_2d() {
  io::MeshData d = two_materials_2d();
  for (Vec3& p : d.points)
    if (p.x() == 1 && p.y() == 1) p = Vec3(1.45, 1.3, 0);
  return d;
}

// The colour bar's column: where the top colour of the map (yellow, 0xfde725) is drawn right
// of the plot; its first yellow and last dark purple (0x440154) rows are the ends of the bar.
struct BarPixels {
  int x = -1, top = -1, bottom = -1;
  double y(double t) const { return bottom - t * (bottom - top); }  ///< t in [0, 1] up
};

BarPixels find_bar(const Image& im) {
  BarPixels b;
  int x0 = im.width, x1 = -1;
  for (int y = 0; y < im.height; ++y)
    for (int x = im.width - 170; x < im.width; ++x)
      if (near(im.at(x, y), {0xfd, 0xe7, 0x25}, 12)) x0 = std::min(x0, x), x1 = std::max(x1, x);
  if (x1 < 0) return b;
  b.x = (x0 + x1) / 2;
  for (int y = 0; y < im.height; ++y) {
    if (b.top < 0 && near(im.at(b.x, y), {0xfd, 0xe7, 0x25}, 12)) b.top = y;
    if (near(im.at(b.x, y), {0x44, 0x01, 0x54}, 12)) b.bottom = y;
  }
  return b;
}

bool dark_near(const Image& im, int x, double y, int rows, int level) {
  for (int dy = -rows; dy <= rows; ++dy) {
    const int row = static_cast<int>(std::lround(y)) + dy;
    const Rgb& p = im.at(x, row);
    if (p[0] <= level && p[1] <= level && p[2] <= level) return true;
  }
  return false;
}

TEST_F(RenderCli, QualityBarShowsTheCellsRangeTicksAndThreshold) {
  const io::MeshData d = sheared_2d();
  io::write_mesh(d, path("mesh.vtu"));
  const std::vector<double> q = cell_qualities(d).scaled_jacobian;
  const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
  ASSERT_GT(*lo, 0.3);  // well above 0: a bar that says 0 says something false
  ASSERT_LT(*lo, 0.9);

  ASSERT_EQ(run(path("mesh.vtu") + " -o " + path("q.png") + " --color quality --size 600x400" +
                " --json " + path("q.json")),
            0);
  const nlohmann::json r = read_json(path("q.json"));
  EXPECT_NEAR(r["range"][0].get<double>(), *lo, 1e-12);  // the cells' own range...
  EXPECT_NEAR(r["range"][1].get<double>(), *hi, 1e-12);
  EXPECT_EQ(r["scale"], nlohmann::json({0.0, 1.0}));  // ...on the fixed scale of quality
  EXPECT_EQ(r["fixed_scale"], true);
  EXPECT_EQ(r["threshold"], 0.3);  // the default threshold of adapt and measure
  std::vector<std::string> labels;
  for (const auto& t : r["ticks"]) labels.push_back(t["label"]);
  EXPECT_EQ(labels, (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));

  // Drawn: a tick mark right of the bar at each tick, the threshold as a black line across.
  const Image im = png_image(path("q.png"));
  const BarPixels bar = find_bar(im);
  ASSERT_GE(bar.x, 0);
  ASSERT_GT(bar.bottom - bar.top, 150) << bar.top << " " << bar.bottom;
  for (double t : {0.2, 0.4, 0.6, 0.8})
    EXPECT_TRUE(dark_near(im, bar.x + 14, bar.y(t), 2, 80)) << "no tick mark at " << t;
  EXPECT_TRUE(dark_near(im, bar.x, bar.y(0.3), 2, 10)) << "no threshold line";
  EXPECT_FALSE(dark_near(im, bar.x, bar.y(0.5), 4, 10));

  // --threshold moves the mark.
  ASSERT_EQ(run(path("mesh.vtu") + " -o " + path("t.png") + " --color quality --size 600x400" +
                " --threshold 0.7 --json " + path("t.json")),
            0);
  EXPECT_EQ(read_json(path("t.json"))["threshold"], 0.7);
  const Image moved = png_image(path("t.png"));
  const BarPixels bar2 = find_bar(moved);
  ASSERT_GE(bar2.x, 0);
  EXPECT_TRUE(dark_near(moved, bar2.x, bar2.y(0.7), 2, 10));
  EXPECT_FALSE(dark_near(moved, bar2.x, bar2.y(0.3), 4, 10));
  EXPECT_EQ(run(path("mesh.vtu") + " -o " + path("x.png") + " --color quality --threshold 2"), 1);
}

TEST_F(RenderCli, FieldBarSpansTheFiniteValuesWithRoundTicks) {
  io::MeshData d = two_materials_2d();  // 8 cells
  const double nan = std::numeric_limits<double>::quiet_NaN();
  d.set_cell_array(cell_array("pressure", {-3.7, 0.5, nan, 12.2, 1, 2, 3, 4}));
  d.set_cell_array(cell_array("flat", std::vector<double>(8, 2.5)));
  io::write_mesh(d, path("mesh.vtu"));
  ASSERT_EQ(
      run(path("mesh.vtu") + " -o " + path("p.png") + " --color pressure --json " + path("p.json")),
      0);
  const nlohmann::json p = read_json(path("p.json"));
  EXPECT_EQ(p["range"], nlohmann::json({-3.7, 12.2}));
  EXPECT_EQ(p["scale"], nlohmann::json({-3.7, 12.2}));
  EXPECT_EQ(p["fixed_scale"], false);
  EXPECT_FALSE(p.contains("threshold"));
  std::vector<std::string> labels;
  for (const auto& t : p["ticks"]) labels.push_back(t["label"]);
  EXPECT_EQ(labels, (std::vector<std::string>{"0", "5", "10"}));

  ASSERT_EQ(
      run(path("mesh.vtu") + " -o " + path("f.png") + " --color flat --json " + path("f.json")), 0);
  const nlohmann::json f = read_json(path("f.json"));
  EXPECT_EQ(f["range"], nlohmann::json({2.5, 2.5}));
  ASSERT_EQ(f["ticks"].size(), 1u);
  EXPECT_EQ(f["ticks"][0]["label"], "2.5");
}

TEST_F(RenderCli, PointArrayColoursTheCellsByTheirNodes) {
  io::MeshData d = two_materials_2d();
  std::vector<double> distance;
  for (const Vec3& p : d.points) distance.push_back(p.x());
  d.set_point_array({"distance", 1, io::ScalarType::float64, distance});
  io::write_mesh(d, path("mesh.vtu"));
  ASSERT_EQ(
      run(path("mesh.vtu") + " -o " + path("d.png") + " --color distance --json " + path("d.json")),
      0);
  const auto [lo, hi] = std::minmax_element(distance.begin(), distance.end());
  const nlohmann::json r = read_json(path("d.json"));
  EXPECT_GT(r["range"][0].get<double>(), *lo);  // cell means, strictly inside the nodes' range
  EXPECT_LT(r["range"][1].get<double>(), *hi);
  EXPECT_TRUE(fs::exists(path("d.png")));
}

}  // namespace
}  // namespace hexadapt
#endif
