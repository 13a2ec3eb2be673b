#include "hexadapt/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "hexadapt/core/error.h"
#include "hexadapt/io/temp_files.h"

namespace hexadapt::io {

namespace {

namespace fs = std::filesystem;

OutputBatch* g_batch = nullptr;  // the open batch, if any

std::string temp_name(const fs::path& target) {
  // The pid makes concurrent writers (parallel make) use distinct temporaries.
  return (target.parent_path() /
          ("." + target.filename().string() + "." + std::to_string(::getpid()) + ".tmp"))
      .string();
}

void rename_or_throw(const std::string& temp, const std::string& target, const std::string& path) {
  if (std::rename(temp.c_str(), target.c_str()) != 0)
    throw IoError(path + ": cannot rename temporary file: " + std::strerror(errno));
}

void sync_or_throw(const std::string& file, const std::string& path) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  const bool ok = fd >= 0 && ::fsync(fd) == 0;
  const int err = errno;
  if (fd >= 0) ::close(fd);
  if (!ok) throw IoError(path + ": cannot sync output file: " + std::strerror(err));
}

}  // namespace

std::string output_target(const std::string& path) {
  fs::path p(path);
  std::error_code ec;
  for (int i = 0; i < 40 && fs::is_symlink(p, ec); ++i) {
    const fs::path link = fs::read_symlink(p, ec);
    if (ec) break;
    p = link.is_absolute() ? link : p.parent_path() / link;
  }
  return p.string();
}

bool writes_directly(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return true;
  return path.rfind("/dev/", 0) == 0 || path.rfind("/proc/", 0) == 0;
}

AtomicFile::AtomicFile(std::string path, bool binary) : path_(std::move(path)) {
  const auto mode = binary ? std::ios::binary | std::ios::trunc : std::ios::trunc;
  if (writes_directly(path_)) {
    out_.open(path_, mode);
    if (!out_) throw IoError(path_ + ": cannot open output: " + std::strerror(errno));
    return;
  }
  target_ = output_target(path_);
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0) mode_ = static_cast<int>(st.st_mode & 07777);
  temp_ = temp_name(target_);
  slot_ = record_temp_file(temp_);
  out_.open(temp_, mode);
  if (!out_) {
    forget_temp_file(slot_);
    throw IoError(path_ + ": cannot create output file: " + std::strerror(errno));
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  if (temp_.empty()) return;
  std::remove(temp_.c_str());
  forget_temp_file(slot_);
}

void AtomicFile::finish() {
  if (out_.is_open()) {  // closed when a library wrote file_name() itself
    out_.flush();
    const bool ok = static_cast<bool>(out_);
    out_.close();
    if (!ok || out_.fail()) throw IoError(path_ + ": write failed (disk full?)");
  }
  if (temp_.empty()) return;
  if (mode_ >= 0 && ::chmod(temp_.c_str(), static_cast<mode_t>(mode_)) != 0)
    throw IoError(path_ + ": cannot keep the file mode: " + std::strerror(errno));
  sync_or_throw(temp_, path_);
}

void AtomicFile::commit() {
  finish();
  if (!temp_.empty() && g_batch) {
    g_batch->pending_.push_back({path_, target_, temp_, slot_});
  } else if (!temp_.empty()) {
    rename_or_throw(temp_, target_, path_);
    forget_temp_file(slot_);
  }
  committed_ = true;
}

OutputBatch::OutputBatch() {
  if (g_batch) throw std::logic_error("an OutputBatch is already open");
  g_batch = this;
}

OutputBatch::~OutputBatch() {
  for (const Pending& p : pending_) {
    std::remove(p.temp.c_str());
    forget_temp_file(p.slot);
  }
  g_batch = nullptr;
}

void OutputBatch::commit() {
  g_batch = nullptr;  // later outputs are written at once
  while (!pending_.empty()) {
    const Pending& p = pending_.front();
    rename_or_throw(p.temp, p.target, p.path);
    forget_temp_file(p.slot);
    pending_.erase(pending_.begin());
  }
}

void write_file_atomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  f.commit();
}

}  // namespace hexadapt::io
