#include "hexadapt/assign/assign.h"

#include <variant>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt::assign {

template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const AssignOptions& options, const dist::Distribution& where) {
  AssignResult r;
  Timer t;
  r.majority = majority_materials(fractions);
  r.times.emplace_back("majority", t.seconds());
  CellMaterials start = r.majority;
  if (options.min_island > 1) {
    t.restart();
    r.islands = remove_islands(mesh, fractions, start, options.min_island, where);
    r.times.emplace_back("islands", t.seconds());
  }
  // A grid of 1e-300 (or 1e300) has no representable cell volumes: it is assigned in its
  // UnitFrame, and the costs, volumes too, go back to its units.
  const UnitFrame frame = far_unit_frame(mesh, where.comm);
  auto assign_in_frame = [&](const M& local) {
    if (options.keep_materials) r.kept = keep_vanished_materials(local, fractions, start, where);
    r.correction = correct_assignment(local, fractions, start, options.correction, where);
    r.balance = material_balance(local, fractions, r.correction.labels, where);
  };
  if (frame.is_identity())
    assign_in_frame(mesh);
  else
    assign_in_frame(to_local(mesh, frame));
  for (double* cost : {&r.correction.cost_initial, &r.correction.cost_final})
    *cost = frame.to_world(*cost, M::dim);
  for (MaterialBalance& b : r.balance)
    for (double* v : {&b.input_volume, &b.assigned_volume}) *v = frame.to_world(*v, M::dim);
  for (const auto& phase : r.correction.times) r.times.push_back(phase);
  if (options.min_island > 1)
    r.small_pieces_final = count_small_pieces(mesh, r.correction.labels, options.min_island, where);
  return r;
}

template <class M>
AssignResult assign_materials(const M& mesh, const Fractions& fractions,
                              const AssignOptions& options) {
  return assign_materials(mesh, fractions, options, dist::Distribution::whole(mesh));
}

template AssignResult assign_materials(const QuadMesh&, const Fractions&, const AssignOptions&,
                                       const dist::Distribution&);
template AssignResult assign_materials(const HexMesh&, const Fractions&, const AssignOptions&,
                                       const dist::Distribution&);
template AssignResult assign_materials(const QuadMesh&, const Fractions&, const AssignOptions&);
template AssignResult assign_materials(const HexMesh&, const Fractions&, const AssignOptions&);

AssignResult assign_materials(const AssignedGrid& grid, const AssignOptions& options) {
  return std::visit([&](const auto& m) { return assign_materials(m, grid.fractions, options); },
                    grid.mesh);
}

}  // namespace hexadapt::assign
