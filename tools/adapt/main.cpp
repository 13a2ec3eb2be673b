// hexadapt-adapt: moves the interface nodes of an assigned grid onto the material interfaces
// and pillows, giving a conformal mesh whose cells each hold one material (paper sec. 5).
#include <string>
#include <variant>
#include <vector>

#include "cli.h"
#include "hexadapt/adapt/adapt.h"
#include "hexadapt/adapt/adapt_io.h"
#include "hexadapt/io/mesh_file.h"

namespace {

using namespace hexadapt;
using cli::Json;

struct Args {
  std::string input;
  std::string method = "base";
  std::vector<std::string> fractions;
  std::string void_material;
  double threshold = 0.3;
  int steps = 16;
  int smooth_iterations = 20;
};

template <class M>
Json result_json(const AdaptResult<M>& r, index_t input_cells) {
  Json j;
  j["cells_in"] = input_cells;
  j["cells"] = r.mesh.n_cells();
  j["nodes"] = r.mesh.n_nodes();
  j["interface_nodes"] = r.n_interface_nodes;
  j["reached"] = r.n_reached;
  j["dist_init"] = r.dist_init;
  j["dist_final"] = r.dist_final;
  j["min_quality"] = r.min_quality;
  j["cells_below_threshold"] = r.n_below_threshold;
  j["cells_inverted"] = r.n_inverted;
  Json steps = Json::array();
  for (const auto& s : r.steps)
    steps.push_back({{"name", s.name},
                     {"min_quality", s.min_quality},
                     {"cells", s.cells},
                     {"seconds", s.seconds}});
  j["steps"] = steps;
  return j;
}

int run_adapt(const CLI::App& app, const Args& args, const cli::CommonOptions& common) {
  cli::refuse_overwrite(common.output, {args.input});
  AdaptOptions options;
  options.method = parse_adapt_method(args.method);
  options.threshold = args.threshold;
  options.steps = args.steps;
  options.smooth.iterations = args.smooth_iterations;
  options.progress = cli::terminal_progress(common);

  Timer clock;
  PhaseTimes times;
  io::MeshData in = io::read_mesh(args.input);
  FractionOptions fo;
  fo.arrays = args.fractions;
  fo.void_material = args.void_material;
  const Fractions fractions = extract_fractions(in, fo, nullptr, args.input);
  const IdVector<CellId, int> material =
      read_material_array(in, fractions.n_materials(), args.input);
  const AnyMesh grid = io::to_mesh(in);
  times.emplace_back("read", clock.seconds());
  clock.restart();

  Json report = cli::report_header(app);
  report["input"] = args.input;
  report["output"] = common.output;
  report["method"] = to_string(options.method);
  report["threshold"] = options.threshold;
  report["steps"] = options.steps;
  report["materials"] = fractions.names();
  io::MeshData out;
  index_t below = 0;
  std::visit(
      [&](const auto& mesh) {
        const auto r = adapt(mesh, fractions, material, options);
        for (const auto& s : r.steps) times.emplace_back(s.name, s.seconds);
        report["result"] = result_json(r, mesh.n_cells());
        below = r.n_below_threshold;
        out = adapt_mesh_data(r, fractions.names());
      },
      grid);
  clock.restart();
  for (auto& kv : cli::provenance(app)) out.metadata.push_back(kv);
  io::write_mesh(out, common.output);
  times.emplace_back("write", clock.seconds());
  report["times"] = cli::phase_times_json(times);
  report["threshold_met"] = below == 0;
  cli::write_report(common, report);
  if (below > 0) {
    log_warning(std::to_string(below) + " output cells have a scaled Jacobian below " +
                std::to_string(options.threshold) + " (the " + args.method +
                " method gives no guarantee); mesh written to " + common.output);
    return cli::target_missed;
  }
  return cli::ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Adapts an assigned grid (material + vf_* cell arrays, from hexadapt-assign) into a\n"
      "conformal mesh whose cells each hold one material, with point arrays 'target' and\n"
      "'distance'. Exit code 3 when output cells end below --threshold.",
      "hexadapt-adapt"};
  Args args;
  cli::CommonOptions common;
  app.add_option("input", args.input, "Assigned grid (.vtu, .vtk, ...)")->required();
  app.add_option("--method", args.method,
                 "base: direct move, global pillowing, smoothing (Fig. 10-a); guaranteed: "
                 "not available yet")
      ->check(CLI::IsMember({"base", "guaranteed"}))
      ->capture_default_str();
  app.add_option("--threshold", args.threshold, "Minimum scaled Jacobian S_q")
      ->check(CLI::Range(-1.0, 1.0))
      ->capture_default_str();
  app.add_option("--steps", args.steps, "Steps of the controlled move")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--smooth-iterations", args.smooth_iterations, "Smoothing sweeps")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--fractions", args.fractions, "Fraction arrays to use, in order")->delimiter(',');
  app.add_option("--void", args.void_material,
                 "Name a material that receives 1 - sum of the given fractions");
  cli::add_common_options(app, common);
  return cli::run(app, argc, argv, common, [&] { return run_adapt(app, args, common); });
}
