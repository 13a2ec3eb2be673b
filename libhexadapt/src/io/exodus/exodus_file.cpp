#include "exodus_file.h"

#include <exodusII.h>
extern "C" {  // the library's internal header has no C++ guard
#include <exodusII_int.h>
}
#include <netcdf.h>
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

// ex_close without its nc_sync: for a file opened read-only, netCDF's sync re-reads the whole
// header, a path in which fuzzing found double frees and heap corruption on hostile files,
// and which has nothing to do. The rest is what ex_close (Exodus 6.02) releases.
int close_read_only(int id) {
  const int status = nc_close(id);
  ex_conv_exit(id);
  for (ex_entity_type t :
       {EX_ELEM_BLOCK, EX_FACE_BLOCK, EX_EDGE_BLOCK, EX_NODE_SET, EX_EDGE_SET, EX_FACE_SET,
        EX_SIDE_SET, EX_ELEM_SET, EX_NODE_MAP, EX_EDGE_MAP, EX_FACE_MAP, EX_ELEM_MAP})
    ex_rm_file_item(id, ex_get_counter_list(t));
  for (obj_stats** s : {&exoII_ed, &exoII_fa, &exoII_eb, &exoII_ns, &exoII_es, &exoII_fs, &exoII_ss,
                        &exoII_els, &exoII_nm, &exoII_edm, &exoII_fam, &exoII_em})
    ex_rm_stat_ptr(id, s);
  return status == NC_NOERR ? 0 : -1;
}

}  // namespace

ExodusFile ExodusFile::create(const std::string& file_name, const std::string& path) {
  quiet();
  int comp_ws = sizeof(double);
  int io_ws = sizeof(double);
  // 64-bit offsets (netCDF "64-bit offset" format): large meshes; no HDF5, no timestamps.
  const int id = ex_create(file_name.c_str(), EX_CLOBBER | EX_LARGE_MODEL, &comp_ws, &io_ws);
  if (id < 0) throw IoError(path + ": cannot create Exodus II file: " + last_message());
  return ExodusFile(id, path, false, io_ws);
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
  return ExodusFile(id, path, true, io_ws);
}

ExodusFile::ExodusFile(ExodusFile&& other) noexcept
    : id_(other.id_),
      path_(std::move(other.path_)),
      reading_(other.reading_),
      stored_float_size_(other.stored_float_size_) {
  other.id_ = -1;
}

ExodusFile::~ExodusFile() {
  if (id_ < 0) return;
  if (reading_)
    close_read_only(id_);
  else
    ex_close(id_);
}

void ExodusFile::check(int status, const std::string& what) const {
  if (status >= 0) return;
  if (reading_) throw InputError(path_, what, last_message());
  throw IoError(path_ + ": " + what + ": " + last_message());
}

void ExodusFile::close() {
  const int id = id_;
  id_ = -1;
  check(reading_ ? close_read_only(id) : ex_close(id), "closing the file");
}

}  // namespace hexadapt::io::detail
