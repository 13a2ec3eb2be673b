#include "file_checks.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <optional>

#include "hexadapt/core/error.h"
#include "hexadapt/io/atomic_file.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::cli {

namespace {

namespace fs = std::filesystem;

// What a file is, by device and inode when it exists, else by its canonical path.
struct FileIdentity {
  bool exists = false;
  dev_t dev = 0;
  ino_t ino = 0;
  std::string canonical;
  bool operator==(const FileIdentity& o) const {
    return exists == o.exists && (exists ? dev == o.dev && ino == o.ino : canonical == o.canonical);
  }
};

FileIdentity identity(const std::string& path) {
  FileIdentity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.dev = st.st_dev;
    id.ino = st.st_ino;
    return id;
  }
  std::error_code ec;
  id.canonical = fs::weakly_canonical(fs::absolute(io::output_target(path), ec), ec).string();
  return id;
}

std::optional<struct stat> stat_of(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return st;
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

bool skipped(const FileArg& f) {
  return f.path.empty() || f.path == "-";
}

// Devices and FIFOs are written directly and may be named twice (-o /dev/null --json /dev/null).
bool written_directly(const FileArg& f) {
  const auto st = stat_of(f.path);
  return io::writes_directly(f.path) && !(st && S_ISDIR(st->st_mode));
}

void check_input(const FileArg& in) {
  const auto st = stat_of(in.path);
  if (st && !S_ISREG(st->st_mode))
    throw IoError(in.path + ": " + in.option + " is " + kind_of(st->st_mode) +
                  ", not a regular file");
}

void check_output(const FileArg& out) {
  const auto st = stat_of(out.path);
  if (st && S_ISDIR(st->st_mode)) throw IoError(out.path + ": " + out.option + " is a directory");
  if (io::writes_directly(out.path)) return;
  const std::string target = io::output_target(out.path);
  fs::path dir = fs::path(target).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IoError(out.path + ": " + out.option + ": directory " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw IoError(out.path + ": " + out.option + ": cannot write in directory " + dir.string());
}

void check_clashes(const std::vector<FileArg>& inputs, const std::vector<FileArg>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const FileArg& o = outputs[i];
    if (skipped(o)) continue;
    const FileIdentity id = identity(o.path);
    for (const FileArg& in : inputs)
      if (!in.path.empty() && identity(in.path) == id)
        throw OptionError(o.option + " " + o.path + " is the same file as " + in.option + " " +
                          in.path + ": refusing to overwrite an input");
    if (written_directly(o)) continue;
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (!skipped(outputs[j]) && identity(outputs[j].path) == id)
        throw OptionError(o.option + " " + o.path + " and " + outputs[j].option + " " +
                          outputs[j].path + " are the same file");
  }
}

}  // namespace

void check_files(const std::vector<FileArg>& inputs, const std::vector<FileArg>& outputs) {
  for (const FileArg& in : inputs)
    if (!in.path.empty()) check_input(in);
  check_clashes(inputs, outputs);
  for (const FileArg& out : outputs) {
    if (skipped(out)) continue;
    if (out.mesh) io::check_mesh_output(out.path, !out.unstructured);
    check_output(out);
  }
}

}  // namespace hexadapt::cli
