#include "input_record.h"

#include <array>
#include <utility>

#include "hexadapt/core/error.h"
#include "hexadapt/io/fractions_reader.h"

namespace hexadapt::cli {

namespace {

const char* reading_flags[] = {"--fractions",  "--void",   "--value-tolerance", "--sum-tolerance",
                               "--zero-below", "--labels", "--label-names",     "--plane",
                               "--step",       "--time"};

Json label_names_json(const std::map<std::int64_t, std::string>& names) {
  Json j = Json::object();
  for (const auto& [value, name] : names) j[std::to_string(value)] = name;
  return j;
}

InputOptions from_json(const Json& j) {
  InputOptions in;
  io::FractionOptions& f = in.fractions;
  f.arrays = j.at("fractions").get<std::vector<std::string>>();
  f.void_material = j.at("void").get<std::string>();
  f.value_tolerance = j.at("value_tolerance").get<double>();
  f.sum_tolerance = j.at("sum_tolerance").get<double>();
  f.zero_below = j.at("zero_below").get<double>();
  f.labels = j.at("labels").get<std::string>();
  for (const auto& [value, name] : j.at("label_names").items())
    f.label_names[std::stoll(value)] = name.get<std::string>();
  in.plane = j.at("plane").get<std::string>();
  if (j.contains("step")) in.time.step = j.at("step").get<std::size_t>();
  if (j.contains("time")) in.time.time = j.at("time").get<double>();
  return in;
}

}  // namespace

std::string input_record(const InputOptions& in, const io::FractionReport& report) {
  const io::FractionOptions& f = in.fractions;
  Json j;
  j["fractions"] = f.arrays;
  j["void"] = f.void_material;
  j["value_tolerance"] = f.value_tolerance;
  j["sum_tolerance"] = report.tolerances.sum_tolerance;
  j["zero_below"] = report.tolerances.zero_below;
  j["labels"] = f.labels;
  j["label_names"] = label_names_json(f.label_names);
  j["plane"] = in.plane;
  if (in.time.step) j["step"] = *in.time.step;
  if (in.time.time) j["time"] = *in.time.time;
  return j.dump();
}

std::optional<InputOptions> carried_input(const io::MeshData& data, const std::string& file) {
  for (const auto& [key, value] : data.metadata) {
    if (key != input_record_key) continue;
    try {
      return from_json(Json::parse(value));
    } catch (const std::exception& e) {
      throw InputError(file, "metadata " + std::string(input_record_key),
                       "not a record of how the input was read (" + std::string(e.what()) +
                           "); give the reading flags instead");
    }
  }
  return std::nullopt;
}

void pass_input_record(const io::MeshData& data, io::MeshData& out) {
  for (const auto& kv : data.metadata)
    if (kv.first == input_record_key) out.metadata.push_back(kv);
}

bool input_options_given(const CLI::App& app) {
  for (const char* flag : reading_flags)
    if (app.count(flag) > 0) return true;
  return false;
}

}  // namespace hexadapt::cli
