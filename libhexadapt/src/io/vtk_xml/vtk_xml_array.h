// Private to the VTK XML reader: the values of one <DataArray> element, whatever its format
// (ascii, inline base64, appended raw or base64) and compression, checked against the number
// of values the data set needs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hexadapt/io/mesh_data.h"
#include "vtk_xml_document.h"

namespace hexadapt::io::detail {

/// A named data array with exactly n_tuples tuples; its type and component count are kept.
/// `components` > 0 requires that many components (e.g. 3 for points).
DataArray read_data_array(const VtkXmlDocument& doc, const pugi::xml_node& e, std::size_t n_tuples,
                          int components = 0);

/// An integer array (connectivity, offsets, types) with exactly n values.
std::vector<std::int64_t> read_int_array(const VtkXmlDocument& doc, const pugi::xml_node& e,
                                         std::size_t n);

/// The strings of a type="String" array (each ends with a NUL byte in the file).
std::vector<std::string> read_string_array(const VtkXmlDocument& doc, const pugi::xml_node& e);

/// Parses n whitespace-separated ascii values of type t into out (double or int64).
/// `text_offset` is the file offset of text[0], for error messages.
void parse_ascii(std::string_view text, std::size_t text_offset, ScalarType t, std::size_t n,
                 double* out, const std::string& file, const std::string& what);
void parse_ascii(std::string_view text, std::size_t text_offset, ScalarType t, std::size_t n,
                 std::int64_t* out, const std::string& file, const std::string& what);
/// Counts the whitespace-separated tokens of text.
std::size_t count_tokens(std::string_view text);

}  // namespace hexadapt::io::detail
