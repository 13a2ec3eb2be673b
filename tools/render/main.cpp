// hexadapt-render: PNG pictures of 2D meshes and of z-plane cuts of 3D meshes, coloured by
// material (with a legend), quality or any cell field (with a colour bar), with the cells'
// edges, optionally another grid (e.g. the input grid) and the `target` arrows drawn over.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "cli.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/mesh_file.h"
#include "picture.h"

namespace {

using namespace hexadapt;

struct Args {
  std::string input, overlay, color = "auto", size = "800x600", title;
  std::vector<double> window;
  double z = 0;
  bool z_given = false, edges = false, no_edges = false, targets = false;
  io::Plane plane = io::Plane::automatic;
  io::ReadOptions time;              ///< --step, --time
  render::ColoringOptions coloring;  ///< --threshold
};

void add_options(CLI::App& app, Args& a) {
  app.add_option("mesh", a.input,
                 "Mesh file to draw (.vtu .vtk .vti .vtr .vts .pvtu .pvtr .pvts .vtm .pvd .txt "
                 ".exo)")
      ->required();
  app.add_option("--color", a.color,
                 "Cell colouring: material (legend of material names), fractions (material "
                 "colours mixed by the vf_ arrays), quality (scaled Jacobian, computed; colour "
                 "bar on the fixed scale 0 to 1, the same in every picture, with --threshold "
                 "marked), none, any cell array (colour bar over the cells' range) or point array "
                 "(each cell the mean of its nodes); auto: "
                 "material when the file has it, else fractions when it has vf_ arrays, else none")
      ->capture_default_str();
  app.add_option("--threshold", a.coloring.threshold,
                 "Minimum scaled Jacobian S_q, marked on the colour bar of --color quality")
      ->check(CLI::Range(-1.0, 1.0))
      ->capture_default_str();
  app.add_option("--z", a.z, "The cutting plane z = value of 3D meshes (default: mid-height)");
  app.add_flag("--edges", a.edges,
               "Always draw the cells' edges (default: when cells are at least 5 pixels wide)");
  app.add_flag("--no-edges", a.no_edges, "Never draw the cells' edges")->excludes("--edges");
  app.add_option("--overlay", a.overlay, "Another mesh whose edges are drawn over, in red");
  app.add_flag("--targets", a.targets, "Draw the `target` point array as arrows from the nodes");
  app.add_option("--size", a.size, "Picture size in pixels, WxH")->capture_default_str();
  app.add_option("--window", a.window, "Part of the plane shown: x0,y0,x1,y1 (default: all)")
      ->delimiter(',')
      ->expected(4);
  app.add_option("--title", a.title, "Line of text above the picture (default: file and field)");
  const std::map<std::string, io::Plane> planes = {{"auto", io::Plane::automatic},
                                                   {"xy", io::Plane::xy},
                                                   {"yz", io::Plane::yz},
                                                   {"xz", io::Plane::xz}};
  app.add_option("--plane", a.plane, "Plane of 2D data sets: auto, xy, yz, xz")
      ->transform(CLI::CheckedTransformer(planes, CLI::ignore_case))
      ->option_text("TEXT:{auto,xy,yz,xz}=auto");
  cli::add_time_options(app, a.time);
}

render::PictureOptions picture_options(const Args& a) {
  render::PictureOptions o;
  std::smatch m;
  const std::regex size_re("([0-9]{1,5})x([0-9]{1,5})");
  if (!std::regex_match(a.size, m, size_re))
    throw OptionError("--size: expected WxH in pixels, got '" + a.size + "'");
  o.width = std::stoi(m[1]);
  o.height = std::stoi(m[2]);
  if (o.width < 16 || o.height < 16 || o.width > 16384 || o.height > 16384)
    throw OptionError("--size: each side must be between 16 and 16384 pixels");
  if (!a.window.empty()) {
    const render::Window w{a.window[0], a.window[1], a.window[2], a.window[3]};
    if (!(w.x1 > w.x0 && w.y1 > w.y0)) throw OptionError("--window: expected x0 < x1 and y0 < y1");
    o.window = w;
  }
  o.edges = a.edges      ? render::Edges::on
            : a.no_edges ? render::Edges::off
                         : render::Edges::automatic;
  return o;
}

// material when there is one, else the blend of the volume fractions, else nothing.
std::string auto_field(const io::MeshData& d) {
  if (d.find_cell_array("material")) return "material";
  for (const auto& a : d.cell_data)
    if (a.name.rfind("vf_", 0) == 0) return "fractions";
  return "none";
}

double mid_height(const io::MeshData& d) {
  if (d.points.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(
      d.points.begin(), d.points.end(), [](const Vec3& p, const Vec3& q) { return p.z() < q.z(); });
  return 0.5 * (lo->z() + hi->z());
}

std::string default_title(const Args& a, const io::MeshData& d, const std::string& field,
                          double z) {
  std::string t = std::filesystem::path(a.input).filename().string() + "  (" + field + ")";
  if (d.dim == 3) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "  z = %.4g", z);
    t += buf;
  }
  return t;
}

// The colour bar as drawn: the cells' range, the scale of the colours, ticks, threshold.
void add_bar_json(cli::Json& json, const render::ColorBar& b) {
  json["range"] = b.has_values ? cli::Json{b.data_min, b.data_max} : cli::Json(nullptr);
  json["scale"] = {b.scale_min, b.scale_max};
  json["fixed_scale"] = b.fixed_scale;
  cli::Json ticks = cli::Json::array();
  for (const render::Tick& t : b.ticks) ticks.push_back({{"value", t.value}, {"label", t.label}});
  json["ticks"] = ticks;
  if (b.threshold) json["threshold"] = *b.threshold;
}

bool ends_with_png(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

int render_mesh(const CLI::App& app, const cli::CommonOptions& common, Args& a) {
  if (common.output.empty()) throw OptionError("-o OUT.png is required");
  if (!ends_with_png(common.output))
    throw OptionError("-o " + common.output + ": render writes PNG pictures only (-o OUT.png)");
  cli::check_files({{"input", a.input}, {"--overlay", a.overlay}},
                   {{"-o", common.output}, {"--json", common.json}});
  render::PictureOptions options = picture_options(a);
  PhaseTimes times;
  const Progress bar = cli::terminal_progress(common);
  io::ReadOptions read = a.time;
  read.plane = a.plane;
  io::MeshData overlay;
  const io::MeshData data = cli::timed_phase(times, bar, "read", [&] {
    if (!a.overlay.empty()) overlay = io::read_mesh(a.overlay, read);
    return io::read_mesh(a.input, read);
  });

  render::SliceOptions slice;
  slice.z = a.z_given ? a.z : mid_height(data);
  std::string field = a.color;
  if (field == "auto") field = auto_field(data);
  const render::Picture pic = cli::timed_phase(times, bar, "slice", [&] {
    render::Picture p;
    p.polygons = render::slice_cells(data, slice);
    p.colors = render::color_cells(data, field, a.coloring);
    if (!a.overlay.empty()) p.overlay = render::slice_cells(overlay, slice);
    if (a.targets) p.arrows = render::target_arrows(data, p.polygons, slice);
    return p;
  });
  if (a.targets && !data.find_point_array("target"))
    log_warning(a.input + ": no `target` point array; --targets draws nothing");
  if (pic.polygons.empty() && data.dim == 3)
    log_warning(a.input + ": no cell crosses the plane z = " + std::to_string(slice.z));
  options.title = a.title.empty() ? default_title(a, data, field, slice.z) : a.title;
  options.progress = bar;
  Timer timer;
  render::write_png(pic, options, common.output);
  times.emplace_back("draw", timer.seconds());

  cli::Json json = cli::report_header(app);
  json["input"] = a.input;
  json["output"] = common.output;
  json["color"] = field;
  json["size"] = {options.width, options.height};
  if (data.dim == 3) json["z"] = slice.z;
  json["cells_drawn"] = pic.polygons.size();
  json["overlay_cells_drawn"] = pic.overlay.size();
  json["arrows_drawn"] = pic.arrows.size();
  if (pic.colors.bar) add_bar_json(json, *pic.colors.bar);
  json["exit_code"] = cli::ok;
  json["times"] = cli::phase_times_json(times);
  cli::write_report(common, json);
  if (!common.quiet)
    std::printf("%s: %zu cells drawn (%s) -> %s\n", a.input.c_str(), pic.polygons.size(),
                field.c_str(), common.output.c_str());
  return cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Draw a 2D mesh, or the cut of a 3D mesh by the plane z = value, to a PNG picture. "
      "Exit codes: 0 drawn, 1 usage, 2 bad input or unwritable output, 4 internal error.",
      "hexadapt-render");
  cli::CommonOptions common;
  Args args;
  add_options(app, args);
  cli::add_common_options(app, common);
  return cli::run(app, argc, argv, common, [&] {
    args.z_given = app.count("--z") > 0;
    return render_mesh(app, common, args);
  });
}
