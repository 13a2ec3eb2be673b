// Writing the geometric model of interface reconstruction (DESIGN sec. 2: "Interface
// surfaces: OpenMesh-readable .om/.obj and a file for ParaView").
//
// For ParaView: a legacy VTK POLYDATA file (.vtk). An unstructured-grid writer cannot hold
// the 2D model (segments) nor mix surfaces with feature curves, so the model has its own
// small writer: interface facets (LINES in 2D, POLYGONS in 3D), feature curves (LINES) and
// corners (VERTICES), with cell arrays material_lo / material_hi (the pair; -1 on features)
// and kind (0 interface, 1 curve, 2 corner); the material names are in the title line.
// The .vtk file is also what the adapt stage reads back (read_model_vtk).
// For OpenMesh users (3D): one PolyMesh of quads per material pair, written with
// OpenMesh::IO (.om or .obj), the face normals pointing from the lower material index to
// the higher one.
#pragma once

#include <string>
#include <vector>

#include "hexadapt/mesh/quad_mesh.h"
#include "hexadapt/reconstruct/model.h"

namespace hexadapt::reconstruct {

/// Atomic. Throws IoError.
void write_model_vtk(const InterfaceModel& model, const std::vector<std::string>& materials,
                     const std::string& path);

struct ModelFile {
  InterfaceModel model;                ///< dim 0 when the file holds no facets
  std::vector<std::string> materials;  ///< from the title line
};

/// Reads back what write_model_vtk wrote (the adapt stage's `--model`). Throws IoError when
/// the file cannot be read, InputError naming the file and line for anything else.
ModelFile read_model_vtk(const std::string& path);

struct ModelPatch {
  int lo = 0, hi = 0;  ///< the material pair
  OmPolyMesh mesh;     ///< its interface quads (vertices duplicated at non-manifold spots)
};

/// The 3D model as one OpenMesh PolyMesh per material pair, pairs in increasing order.
std::vector<ModelPatch> model_patches(const InterfaceModel& model);

/// Writes <stem>.<lo name>-<hi name>.<ext> for every pair (ext "om" or "obj"); returns the
/// paths written. 3D models only (throws OptionError for 2D). Atomic. Throws IoError.
std::vector<std::string> write_model_openmesh(const InterfaceModel& model,
                                              const std::vector<std::string>& materials,
                                              const std::string& stem,
                                              const std::string& ext = "om");

}  // namespace hexadapt::reconstruct
