#include "exodus_file.h"

#include <exodusII.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

// The library prints nothing and never aborts (its default may be verbose): errors come
// back as status codes and the message is fetched with ex_get_err.
void quiet() {
  ex_opts(0);
}

std::string last_message() {
  const char* msg = nullptr;
  const char* func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  std::string out = msg != nullptr ? msg : "";
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out.empty() ? "error " + std::to_string(code) : out;
}

}  // namespace

ExodusFile ExodusFile::create(const std::string& file_name, const std::string& path) {
  quiet();
  int comp_ws = sizeof(double);
  int io_ws = sizeof(double);
  // 64-bit offsets (netCDF "64-bit offset" format): large meshes; no HDF5, no timestamps.
  const int id = ex_create(file_name.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &comp_ws, &io_ws);
  if (id < 0) throw IoError(path + ": cannot create Exodus II file: " + last_message());
  return ExodusFile(id, path, false);
}

ExodusFile ExodusFile::open(const std::string& path) {
  quiet();
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw IoError(path + ": cannot open: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw InputError(path, "", "not a regular file (Exodus II files are read by seeking)");
  int comp_ws = sizeof(double);
  int io_ws = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  if (id < 0)
    throw InputError(path, "", "not a readable Exodus II (netCDF) file: " + last_message());
  return ExodusFile(id, path, true);
}

ExodusFile::ExodusFile(ExodusFile&& other) noexcept
    : id_(other.id_), path_(std::move(other.path_)), reading_(other.reading_) {
  other.id_ = -1;
}

ExodusFile::~ExodusFile() {
  if (id_ >= 0) ex_close(id_);
}

void ExodusFile::check(int status, const std::string& what) const {
  if (status >= 0) return;
  if (reading_) throw InputError(path_, what, last_message());
  throw IoError(path_ + ": " + what + ": " + last_message());
}

void ExodusFile::close() {
  const int id = id_;
  id_ = -1;
  check(ex_close(id), "closing the file");
}

}  // namespace hexadapt::io::detail
