#include "hexadapt/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <unistd.h>

#include "hexadapt/core/error.h"

namespace hexadapt::io {

AtomicFile::AtomicFile(std::string path, bool binary) : path_(std::move(path)) {
  // The pid makes concurrent writers (parallel make) use distinct temporaries.
  const std::filesystem::path target(path_);
  temp_ = (target.parent_path() / ("." + target.filename().string() + "." +
                                   std::to_string(::getpid()) + ".tmp"))
              .string();
  out_.open(temp_, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
  if (!out_) throw IoError(path_ + ": cannot create output file: " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(temp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) throw IoError(path_ + ": write failed (disk full?)");
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw IoError(path_ + ": cannot rename temporary file: " + std::strerror(errno));
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  f.commit();
}

}  // namespace hexadapt::io
