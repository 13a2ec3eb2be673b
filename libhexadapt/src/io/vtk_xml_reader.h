// Private to the VTK XML reader: one function per data set type, and the parts they share
// (the single Piece, point/cell/field data).
#pragma once

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

void read_unstructured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);
void read_image(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);
void read_rectilinear(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);
void read_structured(const VtkXmlDocument& doc, const ReadOptions& options, MeshData& data);

}  // namespace hexadapt::io::detail
