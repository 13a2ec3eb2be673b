// Typed exceptions of the library.
//
// Library code never prints or exits: bad input and impossible requests are thrown as
// subclasses of hexadapt::Error, each carrying where the problem is (file, line, byte offset,
// cell id) so a tool can print one precise line and pick its exit code (DESIGN sec. 2:
// 2 for bad input or IO, 4 for internal errors). Expected outcomes such as "quality target
// not reached" are not errors: they are reported in result structs.
//
// A message that points at an option names its Options field in braces ("{sum_tolerance}
// 0.002 would rescale this cell"), never a tool's flag: the tools show their flag for it
// (--sum-tolerance).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace hexadapt {

/// A token from a file, quoted for an error message: control bytes escaped (\x01), and cut
/// after max_chars characters with "..." (a file may hold a 50 MB "word").
std::string quote_token(std::string_view token, std::size_t max_chars = 40);

/// Base class of every exception thrown by libhexadapt.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// A file or data set that cannot be used as given: malformed, truncated, inconsistent.
/// `file` and `where` ("line 12", "byte 3456", "cell 17") are kept separately so callers can
/// inspect them; what() reads "file: where: message".
class InputError : public Error {
 public:
  InputError(std::string file, std::string where, std::string message);
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, where_, message_;
};

/// A mesh whose topology the kernels cannot represent (a face shared by more than two cells,
/// a cell referring to a missing node, a cell repeating a node).
class MeshError : public Error {
 public:
  explicit MeshError(const std::string& what) : Error(what) {}
};

/// Reading or writing a file failed at the operating-system level.
class IoError : public Error {
 public:
  explicit IoError(const std::string& what) : Error(what) {}
};

/// An option value outside its documented range.
class OptionError : public Error {
 public:
  explicit OptionError(const std::string& what) : Error(what) {}
};

/// The work would need more memory than allowed (an estimate above the given limit).
class ResourceError : public Error {
 public:
  explicit ResourceError(const std::string& what) : Error(what) {}
};

/// A broken invariant inside the library: a bug, never the user's fault.
class InternalError : public Error {
 public:
  explicit InternalError(const std::string& what) : Error(what) {}
};

}  // namespace hexadapt
