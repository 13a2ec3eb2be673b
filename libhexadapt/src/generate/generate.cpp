#include "hexadapt/generate/generate.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "hexadapt/core/error.h"
#include "hexadapt/generate/extrusion.h"
#include "hexadapt/mesh/cell_complex.h"
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
  if (dim != 2 && dim != 3) throw OptionError("--dims takes 2 or 3 values");
  if (!c.defaults(dim).available)
    throw OptionError("case " + c.name + " has no " + std::to_string(dim) + "D version" +
                      (dim == 3 ? " (extrude it with --extrude)" : ""));
  if (o.extrude > 0 && dim != 2)
    throw OptionError("--extrude sweeps a 2D case: give 2 dims, not 3");
  return dim;
}

Bounds pick_bounds(const CaseDefaults& d, const GenerateOptions& o, int dim) {
  const Bounds b = o.bounds ? *o.bounds : d.bounds;
  for (int a = 0; a < dim; ++a)
    if (!(b.lo[a] < b.hi[a]))
      throw OptionError("bounds: the minimum must be below the maximum on every axis");
  return b;
}

/// Sample, then package: the part that is the same for 2D and 3D.
template <class M>
void sample_into(const M& mesh, const Case& c, const Scene& scene, const GenerateOptions& o,
                 GenerateResult& r, Fractions& fractions) {
  SamplingOptions so;
  so.samples = o.samples;
  so.time = r.time;
  so.steps = o.steps;
  so.progress = o.progress;
  SamplingResult s = sample_fractions(mesh, scene, c.materials, so);
  r.steps = s.steps;
  r.shortcut_cells = s.shortcut_cells;
  r.sampled_cells = s.sampled_cells;
  r.mixed_cells = s.mixed_cells;
  r.volumes = s.volumes;
  r.times.emplace_back("sample", s.seconds);
  fractions = std::move(s.fractions);
}

template <class M>
void add_arrays(const M& mesh, const Fractions& f, GenerateResult& r) {
  const index_t nf = f.n_cells();
  r.volumes.assign(r.materials.size(), 0.0);
  for (int m = 0; m < f.n_materials(); ++m) {
    io::DataArray a;
    a.name = "vf_" + r.materials[static_cast<std::size_t>(m)];
    a.values.resize(static_cast<std::size_t>(mesh.n_cells()));
    for (CellId c : id_range<CellId>(mesh.n_cells())) {
      const double v = f(CellId(c.value() % nf), m);  // extruded layers repeat the 2D cells
      a.values[c.idx()] = v;
      r.volumes[static_cast<std::size_t>(m)] += v * mesh.cell_volume(c);
    }
    r.data.set_cell_array(std::move(a));
  }
  r.min_quality = min_quality(mesh);
}

void add_metadata(const Case& c, const GenerateOptions& o, const Bounds& b, GenerateResult& r) {
  std::string mats;
  for (const auto& m : c.materials) mats += (mats.empty() ? "" : ",") + m;
  auto& md = r.data.metadata;
  md.emplace_back("hexadapt_case", c.name);
  md.emplace_back("hexadapt_materials", mats);
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

GenerateResult generate(const GenerateOptions& o) {
  const Case& c = find_case(o.case_name);
  const int dim = pick_dim(c, o);
  const CaseDefaults& d = c.defaults(dim);
  std::array<int, 3> n = d.dims;
  if (!o.dims.empty()) std::copy(o.dims.begin(), o.dims.end(), n.begin());
  for (int a = 0; a < dim; ++a)
    if (n[static_cast<std::size_t>(a)] < 1) throw OptionError("--dims: every axis needs >= 1 cell");
  if (o.extrude < 0) throw OptionError("--extrude must be >= 0");
  const Bounds b = pick_bounds(d, o, dim);
  GenerateResult r;
  r.dim = dim;
  r.materials = c.materials;
  r.time = c.has_flow ? o.time.value_or(d.time) : 0.0;
  if (!c.has_flow && o.time && *o.time != 0)
    log_warning("case " + c.name + " has no flow: --time is ignored");
  const Scene scene = c.build(dim, o.seed);
  JitterOptions jo;
  jo.amplitude = o.jitter;
  jo.min_quality = o.jitter_floor;
  jo.seed = o.seed;
  Fractions f;
  const Vec3 spacing = (b.hi - b.lo).cwiseQuotient(
      Vec3(n[0], n[1], dim == 3 ? n[2] : 1));
  if (dim == 2) {
    QuadMesh mesh = make_quad_grid(n[0], n[1], b.lo, spacing);
    Timer t;
    if (o.jitter > 0) r.jitter = jitter_nodes(mesh, jo);
    r.times.emplace_back("jitter", t.seconds());
    sample_into(mesh, c, scene, o, r, f);
    if (o.extrude > 0) {
      t.restart();
      const HexMesh hex = extrude(mesh, o.extrude, std::min(spacing.x(), spacing.y()));
      r.data = io::from_mesh(hex);
      r.data.structured_cells = {n[0], n[1], o.extrude};
      add_arrays(hex, f, r);
      r.times.emplace_back("extrude", t.seconds());
    } else {
      r.data = io::from_mesh(mesh);
      r.data.structured_cells = {n[0], n[1], 0};
      add_arrays(mesh, f, r);
    }
  } else {
    HexMesh mesh = make_hex_grid(n[0], n[1], n[2], b.lo, spacing);
    Timer t;
    if (o.jitter > 0) r.jitter = jitter_nodes(mesh, jo);
    r.times.emplace_back("jitter", t.seconds());
    sample_into(mesh, c, scene, o, r, f);
    r.data = io::from_mesh(mesh);
    r.data.structured_cells = n;
    add_arrays(mesh, f, r);
  }
  add_metadata(c, o, b, r);
  return r;
}

}  // namespace hexadapt::generate
