// Private to the VTK XML reader: one function per data set type, and the parts they share
// (the single Piece, point/cell/field data).
#pragma once

#include <array>
#include <cstdint>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"
#include "vtk_xml_document.h"

namespace hexadapt::io::detail {

/// The data set element (e.g. <UnstructuredGrid>) and its one Piece. Throws InputError when
/// the element is missing, has no Piece, or has several (multi-piece files are not read).
pugi::xml_node single_piece(const VtkXmlDocument& doc, const pugi::xml_node& dataset);

/// Reads <PointData>, <CellData> of the piece, then as metadata our metadata comment and the
/// String arrays of <FieldData> of the data set, into data (needs n_points / n_cells as the
/// file declares them).
void read_attributes(const VtkXmlDocument& doc, const pugi::xml_node& dataset,
                     const pugi::xml_node& piece, std::size_t n_points, std::size_t n_cells,
                     MeshData& data);

/// A structured piece (ImageData, RectilinearGrid, StructuredGrid) as its file holds it: its
/// extent, its points in file order (i fastest, not yet mapped to a plane, no cells) and its
/// arrays and metadata in `data`.
struct StructuredPiece {
  std::array<std::int64_t, 6> extent{};
  std::array<std::int64_t, 3> dims{};
  MeshData data;
};

/// Reads the one piece of a structured document (doc.type names the data set).
StructuredPiece read_structured_piece(const VtkXmlDocument& doc);

void read_unstructured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);
/// An ImageData, RectilinearGrid or StructuredGrid document (doc.type says which).
void read_structured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);

}  // namespace hexadapt::io::detail
