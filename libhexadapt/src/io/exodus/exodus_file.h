// Private to the Exodus II reader and writer: an open Exodus file, closed when it goes out
// of scope, and the check that turns a failed library call into an exception naming the
// file and the call.
#pragma once

#include <string>

namespace hexadapt::io::detail {

class ExodusFile {
 public:
  /// Creates (clobbers) `file_name`, the file written for `path`. Throws IoError.
  static ExodusFile create(const std::string& file_name, const std::string& path);
  /// Opens `path` for reading. Throws InputError (not an Exodus II file) or IoError.
  static ExodusFile open(const std::string& path);
  ExodusFile(ExodusFile&& other) noexcept;
  ExodusFile& operator=(ExodusFile&&) = delete;
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;
  ~ExodusFile();

  int id() const { return id_; }
  const std::string& path() const { return path_; }
  /// Bytes of the floating-point values as stored in the file (4: float32, 8: float64);
  /// 8 for a file being written.
  int stored_float_size() const { return stored_float_size_; }
  /// Throws when `status` < 0: InputError when reading, IoError when writing; the message
  /// names the call (`what`) and carries the library's own message.
  void check(int status, const std::string& what) const;
  /// Closes the file; throws IoError when the data cannot be flushed.
  void close();

 private:
  ExodusFile(int id, std::string path, bool reading, int stored_float_size)
      : id_(id), path_(std::move(path)), reading_(reading), stored_float_size_(stored_float_size) {}
  int id_ = -1;
  std::string path_;
  bool reading_ = true;
  int stored_float_size_ = 8;
};

}  // namespace hexadapt::io::detail
