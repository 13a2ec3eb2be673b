// Atomic output files: write to a temporary file beside the target, then rename over it.
//
// A crash or an error while writing leaves the previous file (if any) intact and no partial
// output behind. A symlink is followed: the temporary file goes beside its target and
// replaces the target, so the link stays. An existing file keeps its permission mode, and the
// data reaches the disk (fsync) before the rename. A path that exists and is not a regular
// file (a device such as /dev/null, a FIFO), and any path under /dev/ or /proc/, is written
// directly, without a temporary file.
//
// While an OutputBatch is open, commit() leaves the rename to the batch, so that all outputs
// of one run appear together or not at all. Refusing to write over an input of the run is the
// tools' business.
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace hexadapt::io {

/// The file a write to `path` reaches: `path` with its symlinks followed (at most 40).
std::string output_target(const std::string& path);

/// Whether AtomicFile writes `path` directly: it exists and is not a regular file, or it lies
/// under /dev/ or /proc/ (/dev/stdout, /dev/fd/3, /proc/self/fd/1 stay what they are).
bool writes_directly(const std::string& path);

class AtomicFile {
 public:
  /// Opens a temporary file in the directory of the target (or the target itself when it is
  /// not a regular file). Throws IoError.
  explicit AtomicFile(std::string path, bool binary = true);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// The file the data goes to (the temporary file, or the target written directly), for a
  /// library that opens files by name: close stream() first, write this file, then commit().
  const std::string& file_name() const { return temp_.empty() ? path_ : temp_; }
  /// Flushes, fsyncs and closes the temporary file, then renames it to the target (or hands
  /// it to the open OutputBatch). Throws IoError.
  void commit();

 private:
  void finish();

  std::string path_, target_, temp_;  // temp_ is empty when the target is written directly
  std::ofstream out_;
  int mode_ = -1;  // permission bits of the file replaced, -1 when there was none
  int slot_ = -1;  // in the temporary file table (temp_files.h)
  bool committed_ = false;
};

/// All outputs of one run. While it is open (one at a time, on one thread), every
/// AtomicFile::commit() only finishes its temporary file; commit() renames them all, and the
/// destructor removes them when commit() was not reached.
class OutputBatch {
 public:
  OutputBatch();
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  /// Renames every finished temporary file to its target. Throws IoError.
  void commit();

 private:
  friend class AtomicFile;
  struct Pending {
    std::string path, target, temp;
    int slot;
  };
  std::vector<Pending> pending_;
};

/// Writes `content` to `path` atomically.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace hexadapt::io
