#include "hexadapt/reconstruct/reconstruct.h"

#include <variant>

#include "hexadapt/core/error.h"
#include "hexadapt/mesh/cell_complex.h"
#include "hexadapt/mesh/unit_frame.h"

namespace hexadapt::reconstruct {

std::string to_string(Method m) {
  switch (m) {
    case Method::greedy:
      return "greedy";
    case Method::annealing:
      return "annealing";
    case Method::graph_cut:
      return "graphcut";
    case Method::mip:
      return "mip";
  }
  return "?";
}

Method parse_method(const std::string& name) {
  for (Method m : {Method::greedy, Method::annealing, Method::graph_cut, Method::mip})
    if (to_string(m) == name) return m;
  throw OptionError("unknown method '" + name + "': expected greedy, annealing, graphcut or mip");
}

namespace {

double method_bytes(Method m, int n_materials, int dim) {
  switch (m) {
    case Method::greedy:
      return greedy_bytes_per_free_pixel(n_materials, dim);
    case Method::annealing:
      return 0;
    case Method::graph_cut:
      return graph_cut_bytes_per_free_pixel(n_materials, dim);
    case Method::mip:
      return mip_bytes_per_free_pixel(n_materials, dim);
  }
  return 0;
}

// Exact sums over the owned cells: the same bits for any split over ranks.
template <class M>
double unpixelated_discrepancy(const M& mesh, const PixelMesh& px, const Fractions& f,
                               const CellMaterials& assignment, const dist::Distribution& where,
                               double* domain_volume) {
  ExactSum d, total;
  for (index_t i = where.block.owned_cell_first; i < where.block.owned_cell_end; ++i) {
    const CellId c(i);
    const double v = mesh.cell_volume(c);
    total.add(v);
    if (px.cell_block(c) >= 0) continue;
    d.add(2 * (1 - f(c, assignment[c])) * v);  // pure cells: 0 or 2 V
  }
  *domain_volume = dist::exact_sum(where.comm, total);
  return dist::exact_sum(where.comm, d);
}

// Every length, area and volume of a reconstruction made in `frame` back in the grid's units.
void to_world(Reconstruction& out, const UnitFrame& frame, int dim) {
  if (frame.is_identity()) return;
  PixelMesh& px = out.pixels;
  for (Vec3& p : px.block_corners()) p = frame.to_world(p);
  for (double& v : px.volumes()) v = frame.to_world(v, dim);
  px.set_mean_width(frame.to_world(px.mean_width()));
  for (Vec3& p : out.model.points) p = frame.to_world(p);
  ReconstructResult& r = out.result;
  for (double* v : {&r.discrepancy, &r.unpixelated_discrepancy, &r.domain_volume})
    *v = frame.to_world(*v, dim);
}

template <class M>
Reconstruction reconstruct_in_frame(const M& mesh, const Fractions& fractions,
                                    const CellMaterials& assignment,
                                    const ReconstructOptions& options,
                                    const dist::Distribution& where) {
  Reconstruction out;
  ReconstructResult& r = out.result;
  PixelOptions po = options.pixels;
  po.method_bytes_per_free_pixel += method_bytes(options.method, fractions.n_materials(), M::dim);
  Timer t;
  if (options.progress) options.progress("pixels", 0);
  out.pixels = build_pixel_mesh(mesh, fractions, assignment, po);
  r.plan = whole_plan(out.pixels, po, where);
  r.times.emplace_back("pixels", t.seconds());
  t.restart();
  if (options.progress) options.progress(to_string(options.method), 0);
  switch (options.method) {
    case Method::greedy:
      r.greedy = greedy_assign(out.pixels, fractions, options.greedy, where);
      break;
    case Method::annealing:
      r.annealing = annealing_assign(out.pixels, fractions, options.annealing);
      break;
    case Method::graph_cut:
      r.graph_cut = graph_cut_assign(out.pixels, fractions, options.graph_cut);
      break;
    case Method::mip:
      r.mip = mip_assign(out.pixels, fractions, options.mip);
      r.status = to_string(r.mip.status);
      break;
  }
  r.times.emplace_back(to_string(options.method), t.seconds());
  t.restart();
  r.edgecut = edgecut(out.pixels, where);
  r.discrepancy = discrepancy(out.pixels, fractions, where);
  r.unpixelated_discrepancy =
      unpixelated_discrepancy(mesh, out.pixels, fractions, assignment, where, &r.domain_volume);
  if (r.domain_volume > 0)
    r.relative_discrepancy = (r.discrepancy + r.unpixelated_discrepancy) / r.domain_volume;
  r.times.emplace_back("metrics", t.seconds());
  if (options.extract_model) {
    t.restart();
    if (options.progress) options.progress("model", 0);
    out.model = extract_model(mesh, out.pixels, assignment);
    r.times.emplace_back("model", t.seconds());
  }
  if (options.progress) options.progress("done", 1);
  return out;
}

}  // namespace

template <class M>
Reconstruction reconstruct(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const ReconstructOptions& options,
                           const dist::Distribution& where) {
  if (where.comm.size() > 1 && (options.method != Method::greedy || options.extract_model))
    throw OptionError(
        "on several ranks, reconstruct runs the greedy {method} only, without {extract_model}");
  const UnitFrame frame = unit_frame(mesh, where.comm);
  Reconstruction out =
      reconstruct_in_frame(to_local(mesh, frame), fractions, assignment, options, where);
  to_world(out, frame, M::dim);
  return out;
}

template <class M>
Reconstruction reconstruct(const M& mesh, const Fractions& fractions,
                           const CellMaterials& assignment, const ReconstructOptions& options) {
  return reconstruct(mesh, fractions, assignment, options, dist::Distribution::whole(mesh));
}

template Reconstruction reconstruct(const QuadMesh&, const Fractions&, const CellMaterials&,
                                    const ReconstructOptions&);
template Reconstruction reconstruct(const HexMesh&, const Fractions&, const CellMaterials&,
                                    const ReconstructOptions&);
template Reconstruction reconstruct(const QuadMesh&, const Fractions&, const CellMaterials&,
                                    const ReconstructOptions&, const dist::Distribution&);
template Reconstruction reconstruct(const HexMesh&, const Fractions&, const CellMaterials&,
                                    const ReconstructOptions&, const dist::Distribution&);

Reconstruction reconstruct(const AssignedGrid& grid, const ReconstructOptions& options) {
  grid.require_assigned("reconstruct");
  return std::visit(
      [&](const auto& m) { return reconstruct(m, grid.fractions, grid.material, options); },
      grid.mesh);
}

}  // namespace hexadapt::reconstruct
