// The adapt report as JSON (field list and meaning: docs/reports.md).
#include <algorithm>
#include <nlohmann/json.hpp>

#include "hexadapt/adapt/adapt_on_ranks.h"
#include "hexadapt/adapt/adapt_report.h"

namespace hexadapt {

namespace {

using Json = nlohmann::ordered_json;

Json vec(const Vec3& p) {
  return Json::array({p.x(), p.y(), p.z()});
}

double ratio(double a, double b) {
  return b > 0 ? a / b : 0.0;
}

Json figures(const AdaptFigures& f) {
  Json j = {{"cells_in", f.cells_in},
            {"cells", f.cells},
            {"nodes", f.nodes},
            {"interface_nodes", f.interface_nodes},
            {"reached", f.reached},
            {"near_interface", f.near_interface},
            {"blocked_nodes", f.blocked},
            {"frozen_blocked_nodes", f.frozen_blocked},
            {"dist_init", f.dist_init},
            {"dist_final", f.dist_final},
            {"dist_ratio", ratio(f.dist_final, f.dist_init)},
            {"surface_dist_init", f.surface_dist_init},
            {"surface_dist_final", f.surface_dist_final},
            {"surface_dist_ratio", ratio(f.surface_dist_final, f.surface_dist_init)},
            {"min_quality", f.min_quality},
            {"cells_below_threshold", f.below_threshold},
            {"cells_inverted", f.inverted},
            {"cells_below_min_edge", f.below_min_edge},
            {"min_edge_ratio", f.min_edge_ratio},
            {"input_min_quality", f.input_min_quality},
            {"move_smooth_loops", f.loops}};
  if (f.farthest.valid) {
    Json far = {{"node", f.farthest.node},
                {"surface_distance", f.farthest.distance},
                {"local_size", f.farthest.local_size},
                {"position", vec(f.farthest.position)}};
    if (f.farthest.node < 0) far.erase("node");
    j["farthest_node"] = far;
  }
  return j;
}

Json failures(const std::vector<CellFailure>& all, double threshold) {
  Json out = Json::array();
  for (const CellFailure& f : all) {
    Json criteria = Json::array();
    if (f.shape_failed(threshold)) criteria.push_back("threshold");
    if (f.size_failed()) criteria.push_back("min_edge");
    out.push_back({{"cell", f.cell.value()},
                   {"failed", criteria},
                   {"scaled_jacobian", f.scaled_jacobian},
                   {"shortest_edge", f.shortest_edge},
                   {"min_edge_length", f.min_length},
                   {"centroid", vec(f.centroid)}});
  }
  return out;
}

template <class M>
Json layers(const AdaptResult<M>& r) {
  Json pillows = Json::array();
  for (const auto& a : r.interface_pillows)
    pillows.push_back({{"material", a.material},
                       {"rounds", a.rounds},
                       {"kept", a.kept},
                       {"left_out", a.left_out},
                       {"sheet_cells", a.sheet_cells},
                       {"layer_cells", a.layer_cells},
                       {"failing", a.failing}});
  Json cavities = Json::array();
  for (const auto& a : r.cavities) {
    Json seeds = Json::array();
    for (NodeId s : a.seeds) seeds.push_back(s.value());
    cavities.push_back({{"material", a.material},
                        {"seeds", seeds},
                        {"range", a.range},
                        {"cells", a.cells},
                        {"published", a.published},
                        {"min_quality", a.min_quality}});
  }
  return {{"interface_pillows", pillows},
          {"mend_failing", r.mend_failing},
          {"layers", to_string(r.layers)},
          {"other_near_interface", r.other_near_interface},
          {"interface_layer_cells", r.n_interface_layer_cells},
          {"cavities_tried", r.cavities.size()},
          {"cavities_published", r.n_cavities_published},
          {"cells_added_by_pillowing", r.n_cells_added},
          {"cavities", cavities}};
}

Json reach(const ReachResult& r, const char* off, const char* still) {
  return {{off, r.off_surface}, {still, r.still_off}, {"moves", r.moves}, {"passes", r.passes}};
}

template <class M>
Json correction(const AdaptResult<M>& r, double threshold) {
  const TargetCorrectionResult& c = r.correction;
  Json j = {{"ran", c.ran}};
  if (!c.ran) {
    j["skipped"] = c.skipped;
    return j;
  }
  const auto it = std::find_if(r.steps.begin(), r.steps.end(),
                               [](const AdaptStep& s) { return s.name == "correct"; });
  const std::string below = "quads_below_" + nlohmann::json(threshold).dump();
  j["seconds"] = it != r.steps.end() ? it->seconds : 0.0;
  j["surface_quads"] = c.n_faces;
  j["surface_nodes"] = c.n_surface_nodes;
  j["curve_nodes"] = c.n_curve_nodes;
  j["fixed_nodes"] = c.n_fixed_nodes;
  j["unprojected_nodes"] = c.n_unprojected;
  j["off_model_nodes"] = c.n_off_model;
  j["min_quad_quality_before"] = c.min_quality_before;
  j["min_quad_quality_projected"] = c.min_quality_projected;
  j["min_quad_quality_after"] = c.min_quality_after;
  j[below + "_before"] = c.n_poor_before;
  j[below + "_after"] = c.n_poor_after;
  j["mean_target_displacement"] = c.mean_displacement;
  j["max_target_displacement"] = c.max_displacement;
  j["sweeps"] = c.sweeps;
  return j;
}

}  // namespace

std::string adapt_figures_json(const AdaptFigures& f) {
  return figures(f).dump();
}

std::string failures_json(const std::vector<CellFailure>& all, double threshold) {
  return failures(all, threshold).dump();
}

template <class M>
std::string adapt_result_json(const AdaptResult<M>& r, index_t cells_in, double threshold) {
  Json j = figures(adapt_figures(r, cells_in));
  j["failures"] = failures(r.failures, threshold);
  j["input_cells_below_threshold"] = r.bad_input_cells.size();
  Json blocking = Json::array();
  for (const auto& [c, q] : r.blocking_cells)
    blocking.push_back({{"cell", c.value()}, {"quality", q}});
  j["blocking_cells"] = blocking;
  j.update(layers(r));
  j["reach"] = reach(r.reach, "off_surface", "still_off");
  Json steps = Json::array();
  for (const auto& s : r.steps)
    steps.push_back({{"name", s.name},
                     {"min_quality", s.min_quality},
                     {"cells", s.cells},
                     {"seconds", s.seconds}});
  j["steps"] = steps;
  j["correction"] = correction(r, threshold);
  const TargetSpacingResult& sp = r.spacing;
  j["target_spacing"] = {{"short_edges", sp.short_edges}, {"moved_targets", sp.moved},
                         {"left_short", sp.left_short},   {"max_shift", sp.max_shift},
                         {"sweeps", sp.sweeps},           {"swapped", sp.swapped}};
  const LateCavities& late = r.late_cavities;
  j["late_cavities"] = {{"short_nodes", late.short_nodes},
                        {"tried", late.tried},
                        {"published", late.published},
                        {"kept", late.kept}};
  j["late_reach"] = reach(r.late_reach, "short_nodes", "still_short");
  return j.dump();
}

std::string rank_adapt_json(const RankAdaptResult& r) {
  Json j;
  for (const char* key :
       {"cells", "nodes", "interface_nodes", "near_interface", "frozen_blocked_nodes", "adapt_seconds"})
    j[key] = Json::array();
  for (const AdaptFigures& f : r.ranks) {
    j["cells"].push_back(f.cells);
    j["nodes"].push_back(f.nodes);
    j["interface_nodes"].push_back(f.interface_nodes);
    j["near_interface"].push_back(f.near_interface);
    j["frozen_blocked_nodes"].push_back(f.frozen_blocked);
    j["adapt_seconds"].push_back(f.seconds);
  }
  Json runs = Json::array();
  for (const RankRun& run : r.runs)
    runs.push_back({{"layers", to_string(run.layers)},
                    {"mend_failing", run.mend_failing},
                    {"interface_layer_cells", run.interface_layer_cells},
                    {"cavities_published", run.cavities_published}});
  j["runs"] = runs;
  j["cut_layers"] = to_string(r.cut_layers);
  return j.dump();
}

template std::string adapt_result_json(const AdaptResult<QuadMesh>&, index_t, double);
template std::string adapt_result_json(const AdaptResult<HexMesh>&, index_t, double);

}  // namespace hexadapt
