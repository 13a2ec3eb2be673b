// Private to the VTK XML reader: the parsed XML part of a file and where its appended data
// lies. Raw appended data is binary, not XML, so only the text before it is given to pugixml
// (with the AppendedData element closed); arrays then find their bytes by offset.
#pragma once

#include <cstddef>
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "vtk_xml_payload.h"

namespace hexadapt::io::detail {

struct VtkXmlDocument {
  std::string file;
  std::size_t size = 0;  ///< bytes in the whole file
  pugi::xml_document xml;
  pugi::xml_node root;  ///< the VTKFile element
  std::string type;     ///< its type attribute: "UnstructuredGrid", "ImageData", ...
  BinaryLayout layout;
  bool has_appended = false;
  bool appended_base64 = false;     ///< encoding="base64" (else raw)
  std::string_view appended;        ///< the bytes after the '_' marker
  std::size_t appended_offset = 0;  ///< file offset of appended[0]
};

/// Parses `content` (which must outlive the document). Throws InputError for malformed XML,
/// a missing VTKFile element or an unsupported header_type, byte_order or compressor.
void load_vtk_xml(VtkXmlDocument& doc, std::string_view content, const std::string& file);

/// "<Name> at byte N" (the element's offset in the file) for error messages.
std::string place(const pugi::xml_node& element);

/// A required non-negative integer attribute. Throws InputError naming the element.
std::uint64_t count_attribute(const VtkXmlDocument& doc, const pugi::xml_node& e, const char* name);

}  // namespace hexadapt::io::detail
