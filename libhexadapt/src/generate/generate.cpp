#include "hexadapt/generate/generate.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "cells.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/generate/extrusion.h"
#include "hexadapt/io/material_names.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt::generate {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

int pick_dim(const Case& c, const GenerateOptions& o) {
  int dim = o.dims.empty() ? c.default_dim() : static_cast<int>(o.dims.size());
  if (o.extrude > 0 && o.dims.empty()) dim = 2;
  if (dim != 2 && dim != 3) throw OptionError("{dims} takes 2 or 3 values");
  if (!c.defaults(dim).available)
    throw OptionError("case " + c.name + " has no " + std::to_string(dim) + "D version" +
                      (dim == 3 ? " (extrude it with {extrude})" : ""));
  if (o.extrude > 0 && dim != 2)
    throw OptionError("{extrude} sweeps a 2D case: give 2 dims, not 3");
  return dim;
}

Bounds pick_bounds(const CaseDefaults& d, const GenerateOptions& o, int dim) {
  const Bounds b = o.bounds ? *o.bounds : d.bounds;
  if (dim == 2 && (b.lo.z() != 0 || b.hi.z() != 0))
    throw OptionError("a 2D case lives in z = 0: give its bounds as xmin,ymin,xmax,ymax");
  for (int a = 0; a < dim; ++a)
    if (!(b.lo[a] < b.hi[a]))
      throw OptionError("bounds: the minimum must be below the maximum on every axis");
  return b;
}

/// A Cartesian grid as mesh data (structured ids, see structured.h), without a kernel.
io::MeshData grid_data(int dim, const std::array<int, 3>& n, const Vec3& lo, const Vec3& step) {
  io::MeshData d;
  d.dim = dim;
  const int nz = dim == 3 ? n[2] : 0;
  d.points.reserve(static_cast<std::size_t>(n[0] + 1) * static_cast<std::size_t>(n[1] + 1) *
                   static_cast<std::size_t>(nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        d.points.push_back(lo + Vec3(i * step.x(), j * step.y(), dim == 3 ? k * step.z() : 0.0));
  if (dim == 2) {
    for (const auto& c : structured_quads(n[0], n[1]))
      d.cells.insert(d.cells.end(), c.begin(), c.end());
  } else {
    for (const auto& c : structured_hexes(n[0], n[1], n[2]))
      d.cells.insert(d.cells.end(), c.begin(), c.end());
  }
  d.structured_cells = {n[0], n[1], nz};
  return d;
}

/// Cell arrays, per-material volumes and the minimum quality of the output mesh. Per-cell
/// values in parallel, sums in cell order (deterministic). Extruded layers repeat the
/// sampled cells. A grid that was not jittered has equal boxes (scaled Jacobian 1): its
/// cells are not measured one by one.
void add_arrays(const Fractions& f, bool jittered, double box_volume, GenerateResult& r) {
  io::MeshData& d = r.data;
  const auto nf = static_cast<std::size_t>(f.n_cells());
  std::vector<double> volume(static_cast<std::size_t>(d.n_cells()), box_volume);
  if (jittered)
    parallel_for(d.n_cells(), [&](std::int64_t i) {
      volume[static_cast<std::size_t>(i)] = detail::cell_volume(d, static_cast<std::size_t>(i));
    });
  r.volumes.assign(r.materials.size(), 0.0);
  for (int m = 0; m < f.n_materials(); ++m) {
    io::DataArray a;
    a.name = "vf_" + r.materials[static_cast<std::size_t>(m)];
    a.values.resize(volume.size());
    for (std::size_t c = 0; c < volume.size(); ++c) {
      a.values[c] = f(CellId(c % nf), m);
      r.volumes[static_cast<std::size_t>(m)] += a.values[c] * volume[c];
    }
    d.set_cell_array(std::move(a));
  }
  r.min_quality = jittered ? min_scaled_jacobian(d) : 1.0;
}

void add_metadata(const Case& c, const GenerateOptions& o, const Bounds& b, GenerateResult& r) {
  auto& md = r.data.metadata;
  md.emplace_back("hexadapt_case", c.name);
  md.emplace_back(io::material_names_key, io::join_material_names(c.materials));
  md.emplace_back("hexadapt_time", number(r.time));
  md.emplace_back("hexadapt_samples", std::to_string(o.samples));
  md.emplace_back("hexadapt_rk4_steps", std::to_string(r.steps));
  md.emplace_back("hexadapt_seed", std::to_string(o.seed));
  md.emplace_back("hexadapt_jitter", number(o.jitter));
  md.emplace_back("hexadapt_extrude", std::to_string(o.extrude));
  md.emplace_back("hexadapt_bounds", number(b.lo.x()) + "," + number(b.lo.y()) + "," +
                                         number(b.lo.z()) + "," + number(b.hi.x()) + "," +
                                         number(b.hi.y()) + "," + number(b.hi.z()));
}

}  // namespace

namespace {

/// Cells per axis: the case's default overridden by --dims; checked.
std::array<int, 3> pick_dims(const CaseDefaults& d, const GenerateOptions& o, int dim) {
  std::array<int, 3> n = d.dims;
  if (!o.dims.empty()) std::copy(o.dims.begin(), o.dims.end(), n.begin());
  for (int a = 0; a < dim; ++a)
    if (n[static_cast<std::size_t>(a)] < 1) throw OptionError("{dims}: every axis needs >= 1 cell");
  if (o.extrude < 0) throw OptionError("{extrude} must be >= 0");
  if (o.jitter < 0) throw OptionError("{jitter} must be >= 0");
  return n;
}

/// Jitters r.data when asked, then samples the scene on it.
Fractions jitter_and_sample(const Case& c, const Scene& scene, const GenerateOptions& o,
                            GenerateResult& r) {
  const Timer t;
  if (o.jitter > 0) {
    JitterOptions jo;
    jo.amplitude = o.jitter;
    jo.min_quality = o.jitter_floor;
    jo.seed = o.seed;
    r.jitter = jitter_nodes(r.data, jo);
  }
  r.times.emplace_back("jitter", t.seconds());
  SamplingOptions so;
  so.samples = o.samples;
  so.time = r.time;
  so.steps = o.steps;
  so.progress = o.progress;
  SamplingResult s = sample_fractions(r.data, scene, c.materials, so);
  r.steps = s.steps;
  r.shortcut_cells = s.shortcut_cells;
  r.sampled_cells = s.sampled_cells;
  r.mixed_cells = s.mixed_cells;
  r.times.emplace_back("sample", s.seconds);
  return std::move(s.fractions);
}

}  // namespace

GenerateResult generate(const GenerateOptions& o) {
  const Case& c = find_case(o.case_name);
  const int dim = pick_dim(c, o);
  const CaseDefaults& d = c.defaults(dim);
  const std::array<int, 3> n = pick_dims(d, o, dim);
  const Bounds b = pick_bounds(d, o, dim);
  GenerateResult r;
  r.dim = dim;
  r.materials = c.materials;
  r.time = c.has_flow ? o.time.value_or(d.time) : 0.0;
  if (!c.has_flow && o.time && *o.time != 0)
    log_warning("case " + c.name + " has no flow: {time} is ignored");
  const Vec3 spacing = (b.hi - b.lo).cwiseQuotient(Vec3(n[0], n[1], dim == 3 ? n[2] : 1));
  Timer t;
  r.data = grid_data(dim, n, b.lo, spacing);
  r.times.emplace_back("grid", t.seconds());
  const Fractions f = jitter_and_sample(c, c.build(dim, o.seed), o, r);
  t.restart();
  double box_volume = spacing.x() * spacing.y() * (dim == 3 ? spacing.z() : 1.0);
  if (o.extrude > 0) {
    const double thickness = std::min(spacing.x(), spacing.y());
    io::MeshData thick = extrude(r.data, o.extrude, thickness);
    thick.structured_cells = {n[0], n[1], o.extrude};
    r.data = std::move(thick);
    box_volume *= thickness;
  }
  add_arrays(f, o.jitter > 0, box_volume, r);
  r.times.emplace_back("package", t.seconds());
  add_metadata(c, o, b, r);
  return r;
}

}  // namespace hexadapt::generate
