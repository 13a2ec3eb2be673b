// The files of one run, checked before any work (DESIGN sec. 2): every input is a regular file,
// every output can be written, and no output names an input or another output. A run that
// would lose a file stops before it reads anything.
#pragma once

#include <string>
#include <vector>

namespace hexadapt::cli {

/// A file named on the command line, with the option that named it ("input", "-o", "--json").
/// An empty path (option not given) is skipped; "-" is standard output.
struct FileArg {
  std::string option;
  std::string path;
  bool mesh = false;  ///< an output written by io::write_mesh: its extension must be one it writes
  /// A mesh output that is never a structured grid (adapt's, reconstruct's): .vts and .pvts
  /// are refused.
  bool unstructured = false;
};

/// Throws OptionError when an output names the same file as an input or another output (same
/// device and inode when the file exists, same canonical path otherwise), and IoError when an
/// input is a directory, FIFO, device or socket, or an output's directory is missing or not
/// writable, and OptionError when a mesh output's extension is not one io::write_mesh
/// writes. Outputs that exist and are not regular files (/dev/null) are written directly
/// and may repeat.
void check_files(const std::vector<FileArg>& inputs, const std::vector<FileArg>& outputs);

}  // namespace hexadapt::cli
