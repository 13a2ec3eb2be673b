// Reading and writing by extension: the whole file is read into memory once, then parsed by
// the reader of its format (the readers work on in-memory text, which keeps them fast and
// lets the fuzz targets call them directly).
#include "hexadapt/io/mesh_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "collection/vtk_collection.h"
#include "hexadapt/core/error.h"
#include "hexadapt/io/exodus.h"
#include "hexadapt/io/text_case.h"
#include "hexadapt/io/vtk_collection.h"
#include "hexadapt/io/vtk_legacy.h"
#include "hexadapt/io/vtk_xml.h"
#include "vtk_xml/vtk_xml_document.h"

namespace hexadapt::io {

namespace {

std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

// The size of a regular file, or -1 when it has none (a pipe, a terminal).
long file_size(std::FILE* f) {
  if (std::fseek(f, 0, SEEK_END) != 0) return -1;
  const long size = std::ftell(f);
  if (std::fseek(f, 0, SEEK_SET) != 0) return -1;
  return size;
}

std::string read_whole_file(const std::string& path) {
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  const std::unique_ptr<std::FILE, Closer> f(std::fopen(path.c_str(), "rb"));
  if (!f) throw IoError(path + ": cannot open: " + std::strerror(errno));
  std::string content;
  const long size = file_size(f.get());
  if (size > 0) {
    // One allocation and one read; the chunked loop below still catches a file that grew.
    content.resize(static_cast<std::size_t>(size));
    content.resize(std::fread(content.data(), 1, content.size(), f.get()));
  }
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) content.append(buffer, n);
  if (std::ferror(f.get())) throw IoError(path + ": cannot read: " + std::strerror(errno));
  return content;
}

bool is_exodus(const std::string& ext) {
  return ext == ".exo" || ext == ".e" || ext == ".g";
}

// The dataset type a legacy .vtk names (the token after DATASET, upper case), or "" when its
// first lines hold none: the version line, the title line, ASCII or BINARY, then DATASET.
std::string legacy_dataset(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return "";
  char buffer[4096];
  const std::size_t n = std::fread(buffer, 1, sizeof buffer, f);
  std::fclose(f);
  const std::string head(buffer, n);
  std::size_t at = 0;
  for (int line = 0; line < 2 && at != std::string::npos; ++line) {
    at = head.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  if (at == std::string::npos) return "";
  std::vector<std::string> tokens;
  std::string token;
  for (std::size_t k = at; k < head.size() && tokens.size() < 3; ++k) {
    const char c = head[k];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      if (!token.empty()) tokens.push_back(token);
      token.clear();
    } else {
      token += static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    }
  }
  return tokens.size() == 3 && tokens[1] == "DATASET" ? tokens[2] : "";
}

}  // namespace

bool holds_unstructured_mesh(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".vtk") return legacy_dataset(path) == "UNSTRUCTURED_GRID";
  return ext == ".vtu" || ext == ".pvtu" || ext == ".vtm" || ext == ".pvd" || is_exodus(ext);
}

ExodusSets parse_exodus_sets(const std::string& text) {
  if (text == "none") return ExodusSets::none;
  if (text == "boundary") return ExodusSets::boundary;
  if (text == "interfaces") return ExodusSets::interfaces;
  if (text == "all") return ExodusSets::all;
  throw OptionError("unknown Exodus set choice " + quote_token(text) +
                    " (none, boundary, interfaces or all)");
}

MeshData read_mesh(const std::string& path, const ReadOptions& options) {
  const std::string ext = extension_of(path);
  if (is_exodus(ext)) {
    MeshData data = read_exodus(path, options);
    if (options.layers) keep_layers(data, *options.layers, path);
    return data;
  }
  const bool xml = ext == ".vtu" || ext == ".vti" || ext == ".vtr" || ext == ".vts";
  const bool collection = ext == ".pvtu" || ext == ".pvts" || ext == ".pvtr" || ext == ".pvti" ||
                          ext == ".vtm" || ext == ".pvd";
  if (ext != ".vtk" && ext != ".txt" && !xml && !collection)
    throw OptionError(path + ": unknown mesh file extension " + quote_token(ext) +
                      " (supported for reading: .vtk .vtu .vti .vtr .vts .pvtu .pvts .pvtr "
                      ".pvti .vtm .pvd .txt .exo .e .g)");
  const bool structured_collection = ext == ".pvts" || ext == ".pvtr" || ext == ".pvti";
  if (options.layers && collection && !structured_collection)
    throw OptionError(path +
                      ": a window of layers needs a structured grid (.vti .vtr .vts, their "
                      "parallel forms .pvti .pvtr .pvts, or a structured .vtk)");
  const std::string content = read_whole_file(path);
  if (collection) return read_vtk_collection(content, path, options, read_whole_file);
  MeshData data = ext == ".vtk"   ? read_vtk_legacy(content, path, options)
                  : ext == ".txt" ? read_text_case(content, path)
                                  : read_vtk_xml(content, path, options);
  if (options.layers) keep_layers(data, *options.layers, path);
  return data;
}

RankPieces read_rank_pieces(const std::string& path, const ReadOptions& options, int rank,
                            int size) {
  if (extension_of(path) != ".pvtu")
    throw OptionError(path + ": only a .pvtu's pieces are read on several ranks, not a " +
                      quote_token(extension_of(path)));
  detail::VtkXmlDocument doc;
  detail::load_vtk_xml(doc, read_whole_file(path), path);
  if (doc.type != "PUnstructuredGrid")
    throw InputError(path, "", "holds a " + quote_token(doc.type) + ", not a PUnstructuredGrid");
  return detail::read_rank_pieces(doc, {options, read_whole_file, 0}, rank, size);
}

MeshPart merge_rank_pieces(const dist::Communicator& comm, RankPieces pieces,
                           const ReadOptions& options) {
  return detail::merge_on_ranks(comm, std::move(pieces.pieces), pieces.index,
                                options.weld_tolerance, pieces.file);
}

StructuredShape structured_shape(const std::string& path, const ReadOptions& options) {
  const std::string ext = extension_of(path);
  if (ext == ".pvts" || ext == ".pvtr" || ext == ".pvti") {
    detail::VtkXmlDocument doc;
    detail::load_vtk_xml(doc, read_whole_file(path), path);
    return detail::parallel_structured_shape(doc);
  }
  ReadOptions whole = options;
  whole.layers.reset();
  const MeshData data = read_mesh(path, whole);
  if (!data.is_structured())
    throw InputError(path, "",
                     "not a structured grid (.vti .vtr .vts, their parallel forms "
                     ".pvti .pvtr .pvts, or a structured .vtk)");
  return {data.dim, data.structured_cells};
}

void check_mesh_output(const std::string& path, bool structured) {
  const std::string ext = extension_of(path);
  if (!structured && (ext == ".vts" || ext == ".pvts"))
    throw OptionError(path + ": a " + ext +
                      " holds a structured grid, and this mesh is not one: give a .vtu, .pvtu, "
                      ".vtk or .exo");
  if (ext != ".vtu" && ext != ".vts" && ext != ".pvtu" && ext != ".pvts" && ext != ".vtk" &&
      !is_exodus(ext))
    throw OptionError(path + ": unknown mesh file extension " + quote_token(ext) +
                      " (supported for writing: .vtu .vts .pvtu .pvts .vtk .exo .e .g)");
}

void write_mesh(const MeshData& data, const std::string& path, const WriteOptions& options) {
  check_mesh_output(path);
  const std::string ext = extension_of(path);
  if (ext == ".vtu") return write_vtu(data, path, options);
  if (ext == ".vts") return write_vts(data, path, options);
  // Parallel files of one piece: what a job of one rank writes.
  if (ext == ".pvtu") {
    const std::string piece = piece_path(path, 0);
    write_vtu(data, piece, options);
    return write_pvtu(data, {std::filesystem::path(piece).filename().string()}, path);
  }
  if (ext == ".pvts") {
    const std::string piece = piece_path(path, 0);
    write_vts(data, piece, options);
    return write_pvts(
        data, data.structured_cells,
        {{std::filesystem::path(piece).filename().string(), {0, 0, 0}, data.structured_cells}},
        path);
  }
  if (ext == ".vtk") return write_vtk_legacy(data, path);
  return write_exodus(data, path, options);
}

}  // namespace hexadapt::io
