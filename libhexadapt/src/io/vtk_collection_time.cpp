// .pvd time series: the DataSet elements grouped by their timestep attribute, steps in
// increasing time, one chosen by index or by time value.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "hexadapt/core/error.h"
#include "vtk_collection.h"
#include "vtk_xml_array.h"

namespace hexadapt::io::detail {

namespace {

// Steps listed in messages: the first and last few of a long series.
constexpr std::size_t listed_steps = 8;

double time_of(const VtkXmlDocument& doc, const pugi::xml_node& e) {
  const pugi::xml_attribute a = e.attribute("timestep");
  if (!a) return 0;  // ParaView's reading of a DataSet without a time
  double t = 0;
  parse_ascii(a.as_string(), 0, ScalarType::float64, 1, &t, doc.file,
              place(e) + " attribute timestep");
  if (!std::isfinite(t)) throw InputError(doc.file, place(e), "timestep is not a finite number");
  return t;
}

std::string time_text(double t) {
  std::ostringstream s;
  s.precision(10);
  s << t;
  return s.str();
}

std::string steps_text(const std::vector<double>& times) {
  std::string s = std::to_string(times.size()) + (times.size() == 1 ? " step" : " steps") + ":";
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (times.size() > 2 * listed_steps && k == listed_steps) {
      s += " ...";
      k = times.size() - listed_steps;
    }
    s += " " + std::to_string(k) + ": t = " + time_text(times[k]) +
         (k + 1 < times.size() ? "," : "");
  }
  return s;
}

std::size_t step_of_time(const VtkXmlDocument& doc, const pugi::xml_node& collection,
                         const std::vector<double>& times, double t) {
  const double scale =
      std::max({std::abs(times.front()), std::abs(times.back()), times.back() - times.front()});
  const double tolerance = 1e-6 * scale;
  for (std::size_t k = 0; k < times.size(); ++k)
    if (std::abs(times[k] - t) <= tolerance) return k;
  throw InputError(
      doc.file, place(collection),
      "no time step at t = " + time_text(t) + "; the series holds " + steps_text(times));
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
  if (options.step && options.time)
    throw OptionError(doc.file + ": give a time step or a time, not both");
  std::size_t k = 0;
  if (options.step) {
    k = *options.step;
    if (k >= times.size())
      throw InputError(doc.file, place(collection),
                       "no time step " + std::to_string(k) +
                           " (steps count from 0); the series "
                           "holds " +
                           steps_text(times));
  } else if (options.time) {
    k = step_of_time(doc, collection, times, *options.time);
  } else if (times.size() > 1) {
    throw InputError(
        doc.file, place(collection),
        "a time series: choose a step with --step N or --time T; it holds " + steps_text(times));
  }
  return steps[times[k]];
}

}  // namespace hexadapt::io::detail
