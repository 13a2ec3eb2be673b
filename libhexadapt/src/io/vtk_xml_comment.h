// Private to the VTK readers and writers: MeshData::metadata as one XML comment, so that
// readers which reject String field data (meshio 5) still read the file and a person
// opening it sees the provenance (a legacy .vtk carries the same text as a char array). The
// escaping is described in hexadapt/io/vtk_xml.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hexadapt::io::detail {

using Metadata = std::vector<std::pair<std::string, std::string>>;

/// The first line of the comment: marks it as ours among other comments of a file.
inline constexpr std::string_view metadata_comment_title = "hexadapt metadata";

/// The comment text (without "<!--" and "-->"): the title line, then one escaped
/// "key: value" line per entry. Valid inside an XML comment whatever the strings hold.
std::string metadata_comment(const Metadata& metadata);

/// The entries of a comment written by metadata_comment, or nothing when the comment is
/// not one of ours (other title, a line without ": ", an unknown escape).
std::optional<Metadata> parse_metadata_comment(std::string_view comment);

}  // namespace hexadapt::io::detail
