// Atomic output files: write to a temporary file beside the target, then rename over it.
//
// A crash or an error while writing leaves the previous file (if any) intact and no partial
// output behind. Refusing to write over an input of the run is the tools' business.
#pragma once

#include <fstream>
#include <string>

namespace hexadapt::io {

class AtomicFile {
 public:
  /// Opens a temporary file in the directory of `path`. Throws IoError.
  explicit AtomicFile(std::string path, bool binary = true);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// Flushes, closes and renames the temporary file to the target. Throws IoError.
  void commit();

 private:
  std::string path_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `content` to `path` atomically.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace hexadapt::io
