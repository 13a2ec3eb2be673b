#include "vtk_xml_document.h"

#include <charconv>
#include <cstring>

#include "hexadapt/core/error.h"

namespace hexadapt::io::detail {

namespace {

// Splits off raw appended data: returns the XML text to parse (copied, with the
// AppendedData element and the document closed) or nothing when there is no such data.
bool cut_appended(VtkXmlDocument& doc, std::string_view content, std::string& xml_text) {
  const std::size_t tag = content.find("<AppendedData");
  if (tag == std::string_view::npos) return false;
  const std::size_t close = content.find('>', tag);
  if (close == std::string_view::npos)
    throw InputError(doc.file, "byte " + std::to_string(tag),
                     "unterminated <AppendedData> tag (truncated file?)");
  if (content[close - 1] == '/') return false;  // an empty <AppendedData/> is plain XML
  std::size_t mark = close + 1;
  while (mark < content.size() && std::strchr(" \t\r\n", content[mark]) != nullptr) ++mark;
  if (mark >= content.size() || content[mark] != '_')
    throw InputError(doc.file, "byte " + std::to_string(mark),
                     "expected '_' at the start of the appended data");
  doc.has_appended = true;
  doc.appended_offset = mark + 1;
  const std::size_t end = content.rfind("</AppendedData>");
  doc.appended = content.substr(mark + 1, end == std::string_view::npos || end < mark + 1
                                              ? std::string_view::npos
                                              : end - mark - 1);
  xml_text.assign(content.substr(0, close + 1));
  xml_text += "</AppendedData></VTKFile>";
  return true;
}

void read_layout(VtkXmlDocument& doc) {
  const pugi::xml_node r = doc.root;
  const std::string where = place(r);
  const std::string header = r.attribute("header_type").as_string("UInt32");
  if (header != "UInt32" && header != "UInt64")
    throw InputError(doc.file, where,
                     "header_type " + quote_token(header) + ": expected UInt32 or UInt64");
  doc.layout.header64 = header == "UInt64";
  const std::string order = r.attribute("byte_order").as_string("LittleEndian");
  if (order != "LittleEndian" && order != "BigEndian")
    throw InputError(doc.file, where,
                     "byte_order " + quote_token(order) + ": expected LittleEndian or BigEndian");
  doc.layout.big_endian = order == "BigEndian";
  const std::string compressor = r.attribute("compressor").as_string();
  const std::optional<Compressor> c = compressor_of(compressor);
  if (!c)
    throw InputError(doc.file, where,
                     "compressor " + quote_token(compressor) +
                         " is not supported (vtkZLibDataCompressor, vtkLZ4DataCompressor or "
                         "vtkLZMADataCompressor)");
  doc.layout.compressor = *c;
}

}  // namespace

void load_vtk_xml(VtkXmlDocument& doc, std::string_view content, const std::string& file) {
  doc.file = file;
  doc.size = content.size();
  std::string cut;
  const bool appended = cut_appended(doc, content, cut);
  const std::string_view text = appended ? std::string_view(cut) : content;
  // Comments are kept: our metadata is one (see vtk_xml_comment.h).
  const pugi::xml_parse_result ok =
      doc.xml.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_comments);
  if (!ok)
    throw InputError(file, "byte " + std::to_string(ok.offset),
                     std::string("malformed XML: ") + ok.description());
  doc.root = doc.xml.child("VTKFile");
  if (!doc.root) throw InputError(file, "byte 0", "no <VTKFile> element: not a VTK XML file");
  doc.type = doc.root.attribute("type").as_string();
  read_layout(doc);
  if (doc.has_appended) {
    const std::string encoding = doc.root.child("AppendedData").attribute("encoding").as_string();
    if (encoding != "raw" && encoding != "base64")
      throw InputError(
          file, place(doc.root.child("AppendedData")),
          "AppendedData encoding " + quote_token(encoding) + ": expected raw or base64");
    doc.appended_base64 = encoding == "base64";
  }
}

std::string place(const pugi::xml_node& e) {
  std::string s = "<" + std::string(e.name());
  if (const auto name = e.attribute("Name")) s += " Name=\"" + std::string(name.as_string()) + "\"";
  s += ">";
  if (e.offset_debug() >= 0) s += " at byte " + std::to_string(e.offset_debug());
  return s;
}

std::uint64_t count_attribute(const VtkXmlDocument& doc, const pugi::xml_node& e,
                              const char* name) {
  const pugi::xml_attribute a = e.attribute(name);
  const std::string_view v = a.as_string();
  std::uint64_t n = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), n);
  if (!a || r.ec != std::errc() || r.ptr != v.data() + v.size())
    throw InputError(doc.file, place(e),
                     std::string("expected a non-negative integer attribute ") + name +
                         (a ? ", found " + quote_token(v) : ""));
  return n;
}

}  // namespace hexadapt::io::detail
