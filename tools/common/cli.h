// What every hexadapt tool shares: standard flags, exit codes, the JSON report, the progress
// bar on a terminal, and the provenance recorded in every output file (DESIGN sec. 2).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "file_checks.h"
#include "hexadapt/core/log.h"
#include "hexadapt/core/timer.h"
#include "hexadapt/dist/communicator.h"
#include "hexadapt/io/assigned_grid_file.h"
#include "hexadapt/io/fractions_reader.h"
#include "hexadapt/io/mesh_file.h"
#include "memory.h"

namespace hexadapt::cli {

/// Reports keep their keys in insertion order.
using Json = nlohmann::ordered_json;

/// Exit codes of every tool.
enum Exit : int {
  ok = 0,
  usage = 1,          ///< bad command line
  bad_input = 2,      ///< unreadable or invalid input, or an output that cannot be written
  target_missed = 3,  ///< ran, but the requested target (e.g. quality) was not met
  internal = 4,       ///< a bug
  out_of_memory = 5,  ///< the estimate exceeds --max-memory, or an allocation failed
};

struct CommonOptions {
  std::string output;               ///< -o
  std::string json;                 ///< --json
  bool quiet = false;               ///< -q
  int verbose = 0;                  ///< -v (repeatable)
  int threads = 0;                  ///< --threads, 0 = all cores
  std::string max_memory;           ///< --max-memory, empty = the machine's memory
  std::string exodus_sets = "all";  ///< --exodus-sets: none, boundary, interfaces, all
  bool no_string_fields = false;    ///< --no-string-fields
  /// --max-memory in bytes.
  double memory_limit() const { return parse_memory_size(max_memory); }
  /// How the mesh files of the run are written (--exodus-sets, --no-string-fields).
  io::WriteOptions write_options() const;
};

/// Adds -o (when `with_output`), --json, -q, -v, --threads and --max-memory to `app`.
void add_common_options(CLI::App& app, CommonOptions& options, bool with_output = true);

/// Adds the flags of tools that write mesh files: --exodus-sets, --no-string-fields.
void add_write_options(CLI::App& app, CommonOptions& options);

/// How a stage reads its input grid and fractions, with the same flags and meaning in every
/// tool: --fractions, --void, --value-tolerance, --sum-tolerance, --zero-below, --labels,
/// --label-names, --plane, --step, --time.
struct InputOptions {
  io::FractionOptions fractions;
  std::string plane = "auto";  ///< auto, xy, yz or xz
  io::ReadOptions time;        ///< --step and --time (its other fields are unused)
  io::ReadOptions read_options() const;
  /// How the stages read their grid: these fractions, each cell's material from `source`.
  io::AssignedGridOptions grid(io::MaterialSource source) const { return {fractions, source}; }
};

void add_input_options(CLI::App& app, InputOptions& options);

/// --step and --time (the time step of a time series) into `options`.
void add_time_options(CLI::App& app, io::ReadOptions& options);

/// `text` with each Options field that the library names in braces ({sum_tolerance},
/// core/error.h) shown as this tool's flag for it (--sum-tolerance); a name the tool has no
/// flag for stays as it is.
std::string with_flags(const CLI::App& app, std::string_view text);

/// Parses the command line, applies -q/-v/--threads, runs `body` and maps exceptions to exit
/// codes with a one-line message on stderr (library messages and log lines with_flags).
/// `body` returns the exit code. The files `body` writes form one io::OutputBatch: they appear
/// when `body` returns, and none does when it throws or a signal (SIGTERM, SIGINT, SIGHUP)
/// ends the run.
/// The tool runs on one process: started as several (mpirun -np 2), it stops with a usage
/// error.
int run(CLI::App& app, int argc, char** argv, CommonOptions& options,
        const std::function<int()>& body);
/// The same for a tool that runs on the ranks of an MPI job (ranks.h): `body` gets them. On
/// more than one rank, only rank 0 logs and prints errors; an error that dist::on_every_rank did
/// not make common to every rank ends the job (Communicator::abort) with its exit code.
int run_on_ranks(CLI::App& app, int argc, char** argv, CommonOptions& options,
                 const std::function<int(const dist::Communicator&)>& body);

/// An error every rank of a run agreed on: its exit code and the line printed for it.
class RankError : public std::runtime_error {
 public:
  RankError(int code, const std::string& line) : std::runtime_error(line), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

/// A progress callback that draws a bar on stderr when it is a terminal and -q is off;
/// nullptr otherwise.
Progress terminal_progress(const CommonOptions& options);

/// Runs `f` as one phase: shown on the bar (empty, then full when `f` returns; for phases
/// that report no progress of their own) and timed into `times` under `name`.
template <class F>
auto timed_phase(PhaseTimes& times, const Progress& bar, const std::string& name, F&& f) {
  const Timer timer;
  if (bar) bar(name, 0.0);
  auto result = f();
  times.emplace_back(name, timer.seconds());
  if (bar) bar(name, 1.0);
  return result;
}

/// Key/value provenance of this run for output metadata: hexadapt_tool, hexadapt_version and
/// hexadapt_command, the command line with each argument quoted for a POSIX shell where it
/// needs it (spaces, quotes, `$`...), so that it can be pasted back.
std::vector<std::pair<std::string, std::string>> provenance(const CLI::App& app);

/// The report skeleton every tool fills: tool, version, provenance, timings.
Json report_header(const CLI::App& app);
Json phase_times_json(const PhaseTimes& times);

/// Writes the report to --json (atomically; `-` is standard output) when it was given.
void write_report(const CommonOptions& options, const Json& report);

/// Checks of a number flag: > 0 and >= 0, saying so ("must be > 0, got 0"; CLI11's
/// PositiveNumber and NonNegativeNumber print a 309-digit upper bound).
extern const CLI::Validator positive;
extern const CLI::Validator non_negative;

/// Largest --threads accepted; more is a usage error (the OpenMP runtime fails far above).
constexpr int max_threads = 1024;

}  // namespace hexadapt::cli
