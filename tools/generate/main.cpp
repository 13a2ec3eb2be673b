// hexadapt-generate: writes a named synthetic case (a grid with vf_<material> cell arrays).
//   hexadapt-generate triple-point --dims 420,180 --samples 8 -o tp.vf.vtu
//   hexadapt-generate --list
#include <algorithm>
#include <array>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli.h"
#include "hexadapt/core/error.h"
#include "hexadapt/generate/generate.h"
#include "hexadapt/io/mesh_file.h"

namespace hx = hexadapt;
namespace gen = hexadapt::generate;

namespace {

// One case a line under a header, the columns as wide as their longest entry.
void list_cases() {
  std::vector<std::array<std::string, 5>> rows = {{"case", "dims", "flow", "materials", "summary"}};
  for (const auto& c : gen::cases()) {
    std::string mats;
    for (const auto& m : c.materials) mats += (mats.empty() ? "" : ",") + m;
    rows.push_back({c.name, c.d2.available ? (c.d3.available ? "2D/3D" : "2D") : "3D",
                    c.has_flow ? "yes" : "no", mats, c.summary});
  }
  std::array<std::size_t, 5> width{};
  for (const auto& r : rows)
    for (std::size_t k = 0; k < r.size(); ++k) width[k] = std::max(width[k], r[k].size());
  for (const auto& r : rows) {
    std::string line;
    for (std::size_t k = 0; k + 1 < r.size(); ++k)
      line += r[k] + std::string(width[k] + 2 - r[k].size(), ' ');
    std::printf("%s%s\n", line.c_str(), r.back().c_str());
  }
}

gen::Bounds parse_bounds(const std::vector<double>& v) {
  gen::Bounds b;
  if (v.size() == 4) {
    b.lo = hx::Vec3(v[0], v[1], 0);
    b.hi = hx::Vec3(v[2], v[3], 0);
  } else if (v.size() == 6) {
    b.lo = hx::Vec3(v[0], v[1], v[2]);
    b.hi = hx::Vec3(v[3], v[4], v[5]);
  } else {
    throw hx::OptionError("--bounds takes xmin,ymin,xmax,ymax or xmin,ymin,zmin,xmax,ymax,zmax");
  }
  return b;
}

hx::cli::Json report(const CLI::App& app, const gen::GenerateOptions& o,
                     const gen::GenerateResult& r) {
  auto j = hx::cli::report_header(app);
  j["case"] = o.case_name;
  j["dim"] = r.data.dim;
  j["cells"] = r.data.n_cells();
  j["points"] = r.data.n_points();
  j["time"] = r.time;
  j["samples_per_axis"] = o.samples;
  j["rk4_steps"] = r.steps;
  j["seed"] = o.seed;
  j["mixed_cells"] = r.mixed_cells;
  j["shortcut_cells"] = r.shortcut_cells;
  j["sampled_cells"] = r.sampled_cells;
  hx::cli::Json vol = hx::cli::Json::object();
  for (std::size_t m = 0; m < r.materials.size(); ++m) vol[r.materials[m]] = r.volumes[m];
  j["volumes"] = vol;
  j["min_scaled_jacobian"] = r.min_quality;
  if (o.jitter > 0)
    j["jitter"] = {{"amplitude", o.jitter},
                   {"floor", o.jitter_floor},
                   {"moved_nodes", r.jitter.moved_nodes},
                   {"damped_nodes", r.jitter.damped_nodes}};
  j["exit_code"] = hx::cli::ok;
  j["times"] = hx::cli::phase_times_json(r.times);
  return j;
}

struct Args {
  hx::cli::CommonOptions common;
  gen::GenerateOptions o;
  std::vector<double> bounds;
  double time = 0;
  bool list = false;
};

void add_options(CLI::App& app, Args& a) {
  auto& o = a.o;
  app.add_option("case", o.case_name, "Case name (see --list)");
  app.add_option("-o,--output", a.common.output, "Output mesh file (.vtu, .vtk or .exo)");
  hx::cli::add_common_options(app, a.common, false);
  hx::cli::add_write_options(app, a.common);
  app.add_flag("--list", a.list, "List the cases, one a line, and exit");
  app.add_option("--dims", o.dims, "Cells per axis: nx,ny (2D) or nx,ny,nz (3D)")->delimiter(',');
  app.add_option("--bounds", a.bounds,
                 "Domain: xmin,ymin,xmax,ymax or xmin,ymin,zmin,xmax,ymax,zmax")
      ->delimiter(',');
  app.add_option("--time", a.time, "Flow time (default: the case's)");
  app.add_option("--samples", o.samples, "Samples per axis in each cell (s^d per cell)")
      ->capture_default_str();
  app.add_option("--steps", o.steps, "RK4 steps over [0, time] (0: automatic)")
      ->capture_default_str();
  app.add_option("--extrude", o.extrude, "Sweep a 2D case into this many hex layers")
      ->capture_default_str();
  app.add_option("--jitter", o.jitter, "Random node displacement, times the shortest edge, < 0.5")
      ->capture_default_str();
  app.add_option("--jitter-floor", o.jitter_floor, "Scaled Jacobian every jittered cell keeps")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "Seed of the jitter and the seeded shapes")
      ->capture_default_str();
}

int run_generate(const CLI::App& app, Args& a) {
  auto& o = a.o;
  const auto& common = a.common;
  if (a.list) {
    list_cases();
    return hx::cli::ok;
  }
  if (o.case_name.empty()) throw hx::OptionError("a case name is required (see --list)");
  if (common.output.empty()) throw hx::OptionError("an output file is required (-o FILE)");
  hx::cli::check_files({}, {{"-o", common.output, true}, {"--json", common.json}});
  if (!a.bounds.empty()) o.bounds = parse_bounds(a.bounds);
  if (app.count("--time") > 0) o.time = a.time;
  o.progress = hx::cli::terminal_progress(common);
  if (!o.dims.empty()) {
    double cells = std::max(o.extrude, 1);
    for (int n : o.dims) cells *= std::max(n, 0);
    hx::cli::check_memory("generating " + std::to_string(std::llround(cells)) + " cells",
                          cells * hx::cli::generate_bytes_per_cell, common.memory_limit());
  }
  gen::GenerateResult r = gen::generate(o);
  // after the case keys: a legacy .vtk title line keeps only the first 256 characters
  for (auto& kv : hx::cli::provenance(app)) r.data.metadata.push_back(std::move(kv));
  hx::Timer t;
  hx::io::write_mesh(r.data, common.output, common.write_options());
  r.times.emplace_back("write", t.seconds());
  hx::log_info(o.case_name + ": " + std::to_string(r.data.n_cells()) + " cells, " +
               std::to_string(r.mixed_cells) + " mixed, written to " + common.output);
  hx::cli::write_report(common, report(app, o, r));
  return hx::cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Write a synthetic grid with volume fractions (vf_<material> cell arrays)",
               "hexadapt-generate"};
  Args args;
  add_options(app, args);
  return hx::cli::run(app, argc, argv, args.common, [&] { return run_generate(app, args); });
}
