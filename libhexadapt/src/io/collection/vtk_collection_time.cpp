// .pvd time series: the DataSet elements grouped by their timestep attribute, steps in
// increasing time, one chosen by index or by time value as in every time series (time_step.h).
#include <cmath>
#include <map>

#include "../time_step.h"
#include "../vtk_xml/vtk_xml_array.h"
#include "hexadapt/core/error.h"
#include "vtk_collection.h"

namespace hexadapt::io::detail {

namespace {

double time_of(const VtkXmlDocument& doc, const pugi::xml_node& e) {
  const pugi::xml_attribute a = e.attribute("timestep");
  if (!a) return 0;  // ParaView's reading of a DataSet without a time
  double t = 0;
  parse_ascii(a.as_string(), 0, ScalarType::float64, 1, &t, doc.file,
              place(e) + " attribute timestep");
  if (!std::isfinite(t)) throw InputError(doc.file, place(e), "timestep is not a finite number");
  return t;
}

}  // namespace

std::vector<pugi::xml_node> select_time_step(const VtkXmlDocument& doc,
                                             const ReadOptions& options) {
  const pugi::xml_node collection = doc.root.child("Collection");
  if (!collection) throw InputError(doc.file, place(doc.root), "no <Collection> element");
  std::map<double, std::vector<pugi::xml_node>> steps;
  for (const pugi::xml_node e : collection.children("DataSet")) steps[time_of(doc, e)].push_back(e);
  if (steps.empty()) throw InputError(doc.file, place(collection), "no DataSet element");
  std::vector<double> times;
  for (const auto& kv : steps) times.push_back(kv.first);
  return steps[times[select_time_step(times, options, doc.file)]];
}

}  // namespace hexadapt::io::detail
