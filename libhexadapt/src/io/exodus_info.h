// Private to the Exodus II writer and reader: the metadata as info records, lines of at most
// `width` characters, read back whole. An entry starts a line with its key, ": " and its
// value; when longer than a line it goes on in lines starting with '+'. A backslash and a
// line break are written \\ and \n; in a key, a ':' and a leading '+' also get a backslash.
// The Exodus library drops the spaces that end a line: a line never ends with one (a space
// ending an entry is written \s). A line of another writer that is not of that form is read
// as an entry `exodus_info`.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hexadapt::io::detail {

using Metadata = std::vector<std::pair<std::string, std::string>>;

std::vector<std::string> info_lines(const Metadata& metadata, std::size_t width);
Metadata metadata_of_info(const std::vector<std::string>& lines);

}  // namespace hexadapt::io::detail
