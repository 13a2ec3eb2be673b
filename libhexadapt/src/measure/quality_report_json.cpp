// The quality report as JSON (field list and meaning: docs/reports.md).
#include <nlohmann/json.hpp>

#include "hexadapt/measure/quality_report.h"

namespace hexadapt {

namespace {

using Json = nlohmann::ordered_json;

Json vec(const Vec3& p) {
  return Json::array({p.x(), p.y(), p.z()});
}

Json stats_json(const QualityStats& s) {
  return {{"min", s.min}, {"mean", s.mean}, {"max", s.max}};
}

Json node_issues(const std::vector<NodeIssue>& v, bool face, bool other) {
  Json a = Json::array();
  for (const auto& i : v) {
    Json j = {{"node", i.node.value()}, {"position", vec(i.position)}};
    if (face) {
      j["cell"] = i.cell.value();
      j["local_face"] = i.local_face;
    }
    if (other) j["same_as"] = i.other.value();
    a.push_back(j);
  }
  return a;
}

Json cell_issues(const std::vector<CellIssue>& v) {
  Json a = Json::array();
  for (const auto& i : v)
    a.push_back(
        {{"cell", i.cell.value()}, {"scaled_jacobian", i.quality}, {"centroid", vec(i.centroid)}});
  return a;
}

Json ids(const std::vector<CellId>& v) {
  Json a = Json::array();
  for (CellId c : v) a.push_back(c.value());
  return a;
}

Json check_json(const QualityReport& r) {
  Json j;
  j["passed"] = r.check_ok();
  j["representable"] = r.topology_error.empty();
  if (!r.topology_error.empty()) {
    j["error"] = r.topology_error;
    return j;
  }
  const MeshCheckResult& c = r.check;
  j["hanging_nodes"] = c.hanging_nodes;
  j["nonconformal_faces"] = c.nonconformal_faces;
  j["unreferenced_nodes"] = c.unreferenced_nodes;
  j["duplicate_nodes"] = c.duplicate_nodes;
  j["duplicate_distance"] = c.duplicate_distance;
  j["inverted_cells"] = c.inverted_cells;
  j["nonmanifold_nodes"] = c.nonmanifold_nodes;
  j["boundary_faces"] = c.boundary_faces;
  j["first"] = {{"hanging_nodes", node_issues(c.first_hanging, true, false)},
                {"unreferenced_nodes", node_issues(c.first_unreferenced, false, false)},
                {"duplicate_nodes", node_issues(c.first_duplicates, false, true)},
                {"inverted_cells", cell_issues(c.first_inverted)},
                {"nonmanifold_nodes", node_issues(c.first_nonmanifold, false, false)}};
  return j;
}

Json purity_json(const PurityReport& p) {
  Json j;
  j["passed"] = p.ok();
  j["material_array"] = p.has_material;
  j["invalid_material_cells"] = p.invalid_material_cells;
  j["first_invalid"] = ids(p.first_invalid);
  j["fraction_arrays"] = p.fraction_arrays;
  j["mixed_cells"] = p.mixed_cells;
  j["first_mixed"] = ids(p.first_mixed);
  return j;
}

}  // namespace

std::string quality_report_json(const QualityReport& r) {
  Json j;
  j["mesh"] = {{"dim", r.dim}, {"cells", r.n_cells}, {"nodes", r.n_nodes}};
  Json q;
  q["passed"] = r.quality_ok();
  q["threshold"] = r.threshold;
  q["scaled_jacobian"] = stats_json(r.scaled_jacobian);
  q["shape"] = stats_json(r.shape);
  q["histogram"] = {{"lo", r.histogram.lo},
                    {"hi", r.histogram.hi},
                    {"bins", r.histogram.counts.size()},
                    {"counts", r.histogram.counts}};
  q["below_threshold"] = {{"count", r.below_threshold}, {"first", cell_issues(r.first_below)}};
  j["quality"] = q;
  j["mesh_check"] = check_json(r);
  j["purity"] = purity_json(r.purity);
  j["passed"] = r.passed();
  return j.dump();
}

}  // namespace hexadapt
