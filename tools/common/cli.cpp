#include "cli.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/dist/on_every_rank.h"
#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/temp_files.h"
#include "ranks.h"

namespace hexadapt::cli {

namespace {
std::vector<std::string> g_args;  // the command line as given, for provenance

// A number flag's check: a number for which `ok` holds, else "<requirement>, got TEXT".
// CLI11 names the flag in the usage error.
CLI::Validator number_check(bool (*ok)(double), const std::string& requirement,
                            const std::string& description) {
  return CLI::Validator(
      [ok, requirement](std::string& text) -> std::string {
        double v = 0;
        if (CLI::detail::lexical_cast(text, v) && ok(v)) return {};
        return requirement + ", got " + text;
      },
      description);
}

// A tolerance or threshold: a finite number >= 0.
const CLI::Validator finite_non_negative =
    number_check([](double v) { return std::isfinite(v) && v >= 0; },
                 "expected a finite number >= 0", "NUMBER>=0");

const CLI::Validator finite_number =
    number_check([](double v) { return std::isfinite(v); }, "expected a finite number", "NUMBER");

// --label-names: VALUE=NAME entries, VALUE an integer.
std::map<std::int64_t, std::string> parse_label_names(const std::vector<std::string>& entries) {
  std::map<std::int64_t, std::string> names;
  for (const std::string& e : entries) {
    const std::size_t eq = e.find('=');
    std::int64_t value = 0;
    if (eq == std::string::npos || eq + 1 == e.size() ||
        !CLI::detail::lexical_cast(e.substr(0, eq), value))
      throw CLI::ValidationError("--label-names",
                                 "expected VALUE=NAME with an integer VALUE, got " + e);
    if (!names.emplace(value, e.substr(eq + 1)).second)
      throw CLI::ValidationError("--label-names",
                                 "label " + std::to_string(value) + " is named twice");
  }
  return names;
}
}  // namespace

const CLI::Validator positive =
    number_check([](double v) { return v > 0; }, "must be > 0", "POSITIVE");
const CLI::Validator non_negative =
    number_check([](double v) { return v >= 0; }, "must be >= 0", "NONNEGATIVE");

void add_common_options(CLI::App& app, CommonOptions& options, bool with_output) {
  app.set_version_flag("--version", std::string("hexadapt ") + HEXADAPT_VERSION,
                       "Print the version and exit");
  if (with_output) app.add_option("-o,--output", options.output, "Output file")->required();
  app.add_option("--json", options.json, "Write a machine-readable report (JSON) to this file");
  app.add_flag("-q,--quiet", options.quiet, "Only print errors");
  app.add_flag("-v,--verbose", options.verbose, "More messages on stderr (repeat for debug)");
  app.add_option("--threads", options.threads, "Number of threads (0: all cores; at most 1024)")
      ->check(CLI::Range(0, max_threads));
  app.add_option("--max-memory", options.max_memory,
                 "Stop before the work when its memory estimate exceeds this (e.g. 8G, 500M; "
                 "default: the machine's memory, or ulimit -v when lower); exit 5");
}

void add_write_options(CLI::App& app, CommonOptions& options) {
  app.add_option("--exodus-sets", options.exodus_sets,
                 "Side and node sets of Exodus II outputs (.exo .e .g): the domain sides "
                 "(xmin, xmax, ...), the material interfaces, both, or none")
      ->check(CLI::IsMember({"none", "boundary", "interfaces", "all"}))
      ->capture_default_str();
  app.add_flag("--no-string-fields", options.no_string_fields,
               "Leave the String arrays out of .vtu/.vts field data: the material names and "
               "the exact command, which ParaView shows but meshio 5 cannot read (the comment "
               "at the top of the file keeps both, escaped)");
}

io::WriteOptions CommonOptions::write_options() const {
  io::WriteOptions w;
  w.exodus_sets = io::parse_exodus_sets(exodus_sets);
  w.string_fields = !no_string_fields;
  return w;
}

void add_input_options(CLI::App& app, InputOptions& options) {
  io::FractionOptions& f = options.fractions;
  app.add_option("--fractions", f.arrays,
                 "Fraction cell arrays, in material order (default: every vf_<material>): one "
                 "argument per array, or names separated by commas; an argument naming an "
                 "array is taken whole (\"Volume Fraction for Body, Nose\")");
  app.add_option("--void", f.void_material,
                 "Name a material that receives 1 - sum of the others: a new material after "
                 "them, or, when a fraction array of that material exists (vf_NAME), that "
                 "material recomputed as the remainder instead of read");
  app.add_option("--value-tolerance", f.value_tolerance,
                 "How far outside [0,1] a fraction may be and still be clipped")
      ->check(finite_non_negative)
      ->capture_default_str();
  app.add_option_function<double>(
         "--sum-tolerance", [&f](const double& v) { f.sum_tolerance = v; },
         "How far from 1 a cell's sum may be and still be rescaled (default: 1e-4; for "
         "fractions stored as float32 at least 8 x materials x 2^-23, their rounding)")
      ->check(finite_non_negative);
  app.add_option_function<double>(
         "--zero-below", [&f](const double& v) { f.zero_below = v; },
         "Fractions below this are traces, set to 0 (default: 1e-5; for fractions stored as "
         "float32 at least 8 x materials x 2^-23, their rounding)")
      ->check(finite_non_negative);
  app.add_option("--labels", f.labels,
                 "Integer cell array of material ids (a label map): one material per value, "
                 "named label_<value>; instead of fraction arrays");
  app.add_option_function<std::vector<std::string>>(
         "--label-names",
         [&f](const std::vector<std::string>& entries) {
           f.label_names = parse_label_names(entries);
         },
         "Names of --labels values: VALUE=NAME,... (e.g. 1=steel,2=air)")
      ->delimiter(',');
  app.add_option("--plane", options.plane, "Plane of 2D data: auto, xy, yz, xz")
      ->check(CLI::IsMember({"auto", "xy", "yz", "xz"}))
      ->capture_default_str();
  add_time_options(app, options.time);
}

void add_time_options(CLI::App& app, io::ReadOptions& options) {
  auto* step = app.add_option_function<std::size_t>(
      "--step", [&options](const std::size_t& k) { options.step = k; },
      "Time step to read from a time series (.pvd .exo), counted from 0");
  app.add_option_function<double>(
         "--time", [&options](const double& t) { options.time = t; },
         "Time value of the step to read from a time series (.pvd .exo)")
      ->check(finite_number)
      ->excludes(step);
}

io::ReadOptions InputOptions::read_options() const {
  io::ReadOptions r = time;
  r.plane = plane == "xy"   ? io::Plane::xy
            : plane == "yz" ? io::Plane::yz
            : plane == "xz" ? io::Plane::xz
                            : io::Plane::automatic;
  return r;
}

namespace {

// The flag of an Options field (a nested one by its path, "cavity.range"): its name with
// dashes for '_' and '.', or where the two differ, this.
const std::map<std::string, std::string, std::less<>> flag_names = {
    {"void_material", "void"}, {"move.steps", "steps"}, {"move.drag", "drag"},
    {"extract_model", "model"}};

std::string flag_of(const CLI::App& app, std::string_view field) {
  if (field.empty() ||
      field.find_first_not_of("abcdefghijklmnopqrstuvwxyz_.0123456789") != std::string_view::npos)
    return {};
  const auto named = flag_names.find(field);
  std::string flag = "--" + (named != flag_names.end() ? named->second : std::string(field));
  std::replace(flag.begin(), flag.end(), '_', '-');
  std::replace(flag.begin(), flag.end(), '.', '-');
  return app.get_option_no_throw(flag) ? flag : std::string();
}

}  // namespace

std::string with_flags(const CLI::App& app, std::string_view text) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t open; (open = text.find('{', from)) != std::string_view::npos;) {
    const std::size_t close = text.find('}', open);
    if (close == std::string_view::npos) break;
    const std::string flag = flag_of(app, text.substr(open + 1, close - open - 1));
    out += text.substr(from, (flag.empty() ? close + 1 : open) - from);
    out += flag;
    from = close + 1;
  }
  out += text.substr(from);
  return out;
}

namespace {

// The exit code of an exception a run ended with, and the line it prints.
std::pair<int, std::string> describe(const CLI::App& app, const std::exception_ptr& error) {
  const std::string tool = app.get_name();
  try {
    std::rethrow_exception(error);
  } catch (const RankError& e) {
    return {e.code(), e.what()};
  } catch (const dist::CommonError& e) {
    return describe(app, e.original());
  } catch (const OptionError& e) {
    return {usage, tool + ": error: " + with_flags(app, e.what())};
  } catch (const InputError& e) {
    return {bad_input, tool + ": error: " + with_flags(app, e.what())};
  } catch (const MeshError& e) {
    return {bad_input, tool + ": error: invalid mesh: " + with_flags(app, e.what())};
  } catch (const IoError& e) {
    return {bad_input, tool + ": error: " + with_flags(app, e.what())};
  } catch (const ResourceError& e) {
    return {out_of_memory, tool + ": error: " + with_flags(app, e.what())};
  } catch (const std::bad_alloc&) {
    const double estimate = last_memory_estimate();
    return {out_of_memory,
            tool + ": error: out of memory" +
                (estimate > 0 ? " (the estimate for this run was about " + size_text(estimate) + ")"
                              : std::string()) +
                ": give the tool more memory (ulimit -v, a larger machine) or a smaller "
                "input; --max-memory stops a run whose estimate is too large before it starts"};
  } catch (const std::exception& e) {
    return {internal, tool + ": internal error: " + e.what()};
  }
}

int run_body(CLI::App& app, int argc, char** argv, CommonOptions& options, const Ranks& ranks,
             const std::function<int(const dist::Communicator&)>& body) {
  const dist::Communicator& comm = ranks.comm();
  g_args.assign(argv, argv + argc);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? ok : usage;
  }
  const std::string tool = app.get_name();
  // Every rank logs the same lines: rank 0 prints them.
  set_log_sink(
      [tool, &app](LogLevel level, std::string_view message) {
        const char* tag = level >= LogLevel::error     ? "error: "
                          : level == LogLevel::warning ? "warning: "
                                                       : "";
        std::cerr << tool << ": " << tag << with_flags(app, message) << '\n';
      },
      comm.rank() > 0        ? LogLevel::off
      : options.quiet        ? LogLevel::error
      : options.verbose >= 2 ? LogLevel::debug
      : options.verbose == 1 ? LogLevel::info
                             : LogLevel::warning);
  io::remove_temp_files_on_signals();
  try {
    set_threads(options.threads);
    (void)options.memory_limit();  // a bad --max-memory is a usage error before any work
    io::OutputBatch outputs;
    const int code = body(comm);
    outputs.commit();
    return code;
  } catch (const RankError& e) {
    if (comm.rank() == 0) std::cerr << e.what() << '\n';
    return e.code();
  } catch (const dist::CommonError& e) {
    const auto [code, line] = describe(app, e.original());
    if (comm.rank() == 0) std::cerr << line << '\n';
    return code;
  } catch (...) {
    const auto [code, line] = describe(app, std::current_exception());
    if (comm.size() > 1) {
      std::cerr << "rank " << comm.rank() << ": " << line << '\n';
      comm.abort(code);
    }
    std::cerr << line << '\n';
    return code;
  }
}

// Starts the ranks, then runs the tool on them.
int start(CLI::App& app, int argc, char** argv, CommonOptions& options,
          const std::function<int(const dist::Communicator&)>& body) {
  std::unique_ptr<Ranks> ranks;
  try {
    ranks = std::make_unique<Ranks>(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << app.get_name() << ": error: " << e.what() << '\n';
    return usage;
  }
  return run_body(app, argc, argv, options, *ranks, body);
}

}  // namespace


int run(CLI::App& app, int argc, char** argv, CommonOptions& options,
        const std::function<int()>& body) {
  return start(app, argc, argv, options, [&](const dist::Communicator& comm) {
    if (comm.size() > 1)
      throw RankError(usage, app.get_name() + ": error: runs on one process, not on the " +
                                 std::to_string(comm.size()) + " of this MPI job");
    return body();
  });
}

int run_on_ranks(CLI::App& app, int argc, char** argv, CommonOptions& options,
                 const std::function<int(const dist::Communicator&)>& body) {
  return start(app, argc, argv, options, body);
}

Progress terminal_progress(const CommonOptions& options) {
  if (options.quiet || !::isatty(STDERR_FILENO)) return nullptr;
  return [](std::string_view phase, double fraction) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\r%-24.*s [%.*s%*s] %3d%%", static_cast<int>(phase.size()), phase.data(),
                 filled, "##############################", width - filled, "",
                 static_cast<int>(fraction * 100 + 0.5));
    if (fraction >= 1.0) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

namespace {
// An argument as a POSIX shell reads it back: as it is when it holds only characters no shell
// treats specially, else in single quotes (a quote inside as '\''), so that the recorded
// command can be pasted back.
std::string shell_word(const std::string& arg) {
  static const char* plain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_@%+=:,./-";
  if (!arg.empty() && arg.find_first_not_of(plain) == std::string::npos) return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}
}  // namespace

std::vector<std::pair<std::string, std::string>> provenance(const CLI::App& app) {
  std::string line;
  for (std::size_t i = 0; i < g_args.size(); ++i) {
    if (i) line += ' ';
    line += i == 0 ? app.get_name() : shell_word(g_args[i]);
  }
  return {{"hexadapt_tool", app.get_name()},
          {"hexadapt_version", HEXADAPT_VERSION},
          {"hexadapt_command", line}};
}

Json report_header(const CLI::App& app) {
  Json j;
  for (const auto& [k, v] : provenance(app)) j[k.substr(9)] = v;  // drop "hexadapt_"
  return j;
}

Json phase_times_json(const PhaseTimes& times) {
  Json j = Json::object();
  for (const auto& [name, seconds] : times) j[name] = seconds;
  return j;
}

void write_report(const CommonOptions& options, const Json& report) {
  if (options.json.empty()) return;
  if (options.json == "-") {
    std::cout << report.dump(2) << '\n' << std::flush;
    if (!std::cout) throw IoError("--json -: cannot write to standard output");
    return;
  }
  io::write_file_atomically(options.json, report.dump(2) + "\n");
}

}  // namespace hexadapt::cli
