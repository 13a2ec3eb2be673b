// Exodus II files (Sandia's format: Sculpt's input and output, what Lagrangian codes read),
// through Debian's libexodusii (the Exodus C API on netCDF). DESIGN sec. 2.
//
// Writing: the nodes in their order, the cells grouped into one element block per material
// (block id = material index + 1, named after the material; a material without cells gets
// no block), QUAD4 elements with num_dim 2 or HEX8 elements with num_dim 3. The element id
// map holds each element's cell id + 1 (so a cell keeps its number), the node id map is the
// identity. Cell arrays become element variables and point arrays nodal variables (with
// _x, _y, _z suffixes for 3 components) at one time step, time 0. Side and node sets
// (WriteOptions::exodus_sets): per domain side `xmin`, `xmax`, `ymin`, `ymax` (`zmin`,
// `zmax`), by the dominant direction from the cell's centre to the face's centre; per pair
// of touching materials a and b, side sets `a_b` (the faces of a's cells against b) and
// `b_a`, and one node set `a_b` (a before b in the material order). QA record: tool and
// version (date and time left empty: the same mesh gives the same bytes); info records: a
// line "hexadapt metadata", then each metadata entry "key: value" in lines of 80 characters,
// its further lines starting with '+' (a backslash and a line break in it written \\ and \n).
// Names longer than Exodus' default of 32 characters raise the file's name length (up to
// 255).
//
// Reading: QUAD4 (num_dim 2) or HEX8 (num_dim 3) element blocks; the cells in block order;
// element variables at the chosen time step (ReadOptions::step or ::time, needed when the
// file holds several steps) become cell arrays and nodal variables point arrays (P_x, P_y,
// P_z in a row: the 3-component array P), so fractions stored as element variables (as Sculpt
// reads them) are found by --fractions or the vf_ convention. Without a `material` element
// variable, the block of each cell becomes the `material` cell array (block order) and the
// block names the `materials` metadata entry. Info records that start with the line
// "hexadapt metadata" become the metadata again; others (other writers', and ours before that
// line, which cut entries at 80 characters) are left as they are.
#pragma once

#include <string>

#include "hexadapt/io/mesh_data.h"
#include "hexadapt/io/mesh_file.h"

namespace hexadapt::io {

/// Throws IoError (cannot create or write) or OptionError (no cells, a path that is not a
/// regular file, sizes beyond the 32-bit ids of the format).
void write_exodus(const MeshData& data, const std::string& path, const WriteOptions& options);

/// Throws InputError naming the file and what is wrong (not an Exodus file, element type,
/// sizes, node ids, time step), IoError when the file cannot be opened.
MeshData read_exodus(const std::string& path, const ReadOptions& options);

}  // namespace hexadapt::io
