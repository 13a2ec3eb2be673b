// Private to the Exodus II writer and reader: the metadata as info records, lines of at most
// `width` characters, read back whole. The first line is `info_marker`; then an entry starts a
// line with its key, ": " and its value, and when longer than a line goes on in lines
// starting with '+'. A backslash and a line break are written \\ and \n; in a key, a ':' and
// a leading '+' also get a backslash. The Exodus library drops the spaces that end a line: a
// line never ends with one (a space ending an entry is written \s). Info records without the
// marker (other writers', and ours before it, which cut entries at 80 characters) are text
// for people: they give no metadata.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hexadapt::io::detail {

using Metadata = std::vector<std::pair<std::string, std::string>>;

inline constexpr const char* info_marker = "hexadapt metadata";

std::vector<std::string> info_lines(const Metadata& metadata, std::size_t width);
Metadata metadata_of_info(const std::vector<std::string>& lines);

}  // namespace hexadapt::io::detail
