// hexadapt-render end to end: meshes written by the library, the built tool run on them,
// the PNG's size read from its header and its pixels decoded with cairo.
#ifdef HEXADAPT_HAVE_RENDER
#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_file.h"
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
  ASSERT_EQ(run(path("cube.vtu") + " -o " + path("low.png") + " --z 0.5 --size 300x200 --no-edges"), 0);
  ASSERT_EQ(run(path("cube.vtu") + " -o " + path("high.png") + " --z 1.5 --size 300x200 --no-edges"), 0);
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

}  // namespace
}  // namespace hexadapt
#endif
