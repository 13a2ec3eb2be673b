// The size report as JSON (field list and meaning: docs/reports.md). Infinite and NaN
// values are written as null.
#include <nlohmann/json.hpp>

#include "hexadapt/measure/size_report.h"

namespace hexadapt {

namespace {

using Json = nlohmann::ordered_json;

Json histogram_json(const SizeHistogram& h) {
  if (h.counts.empty()) return nullptr;
  return {{"lower", h.lower}, {"counts", h.counts}};
}

Json below_json(const SizeFigures& f) {
  Json first = Json::array();
  for (const SizeBreach& b : f.first_below)
    first.push_back({{"cell", b.cell.value()},
                     {"shortest_edge", b.shortest_edge},
                     {"local_size", b.local_size},
                     {"ratio", b.ratio},
                     {"centroid", {b.centroid.x(), b.centroid.y(), b.centroid.z()}}});
  return {{"count", f.below_min_edge}, {"first", first}};
}

Json figures_json(const SizeFigures& f) {
  Json j;
  if (f.has_local_size) {
    j["relative_edge"] = {{"min", f.min_relative_edge}, {"max", f.max_relative_edge}};
    j["below_min_edge"] = below_json(f);
  } else {
    j["relative_edge"] = nullptr;
    j["below_min_edge"] = nullptr;
  }
  const QualityStats& e = f.edge_ratio;
  j["edge_ratio"] = {{"min", e.min},
                     {"mean", e.mean},
                     {"max", e.max},
                     {"histogram", histogram_json(f.edge_ratio_histogram)}};
  const QualityStats& t = f.time_step;
  j["time_step"] = {{"min", t.min},
                    {"mean", t.mean},
                    {"max", t.max},
                    {"min_cell", f.time_step_min_cell.value()},
                    {"median", f.time_step_median},
                    {"histogram", histogram_json(f.time_step_histogram)}};
  return j;
}

const char* source_name(LocalSizeSource s) {
  switch (s) {
    case LocalSizeSource::array:
      return "array";
    case LocalSizeSource::reference:
      return "reference";
    case LocalSizeSource::none:
      break;
  }
  return nullptr;
}

}  // namespace

std::string size_report_json(const SizeReport& r) {
  Json j;
  j["passed"] = r.passed();
  j["min_edge"] = r.min_edge;
  j["checked"] = r.checked();
  if (!r.checked()) j["not_checked"] = r.not_checked;
  const char* source = source_name(r.local_size);
  j["local_size"] = source ? Json(source) : Json(nullptr);
  if (r.local_size == LocalSizeSource::reference) j["outside_reference"] = r.outside_reference;
  const Json mesh = figures_json(r.mesh);
  for (const auto& [key, value] : mesh.items()) j[key] = value;
  if (r.has_reference) {
    j["reference"] = figures_json(r.reference);
    j["time_step_ratio"] = r.time_step_ratio;
  }
  return j.dump();
}

}  // namespace hexadapt
