#include "hexadapt/generate/jitter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cells.h"
#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "random.h"

namespace hexadapt::generate {

namespace {

constexpr std::array<std::array<int, 2>, 4> quad_edges = {{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};

std::vector<double> shortest_edges(const io::MeshData& mesh) {
  std::vector<double> h(mesh.points.size(), std::numeric_limits<double>::infinity());
  const auto npc = static_cast<std::size_t>(mesh.nodes_per_cell());
  const auto visit = [&](std::size_t c, int a, int b) {
    const NodeId na = mesh.cells[c * npc + static_cast<std::size_t>(a)];
    const NodeId nb = mesh.cells[c * npc + static_cast<std::size_t>(b)];
    const double len = (mesh.points[na.idx()] - mesh.points[nb.idx()]).norm();
    h[na.idx()] = std::min(h[na.idx()], len);
    h[nb.idx()] = std::min(h[nb.idx()], len);
  };
  for (std::size_t c = 0; c < static_cast<std::size_t>(mesh.n_cells()); ++c) {
    if (mesh.dim == 3)
      for (const auto& e : ref_hex::edges) visit(c, e[0], e[1]);
    else
      for (const auto& e : quad_edges) visit(c, e[0], e[1]);
  }
  return h;
}

std::vector<Vec3> displacements(const io::MeshData& mesh, const JitterOptions& o) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const auto h = shortest_edges(mesh);
  std::vector<Vec3> d(mesh.points.size(), Vec3::Zero());
  parallel_for(mesh.n_points(), [&](std::int64_t i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec3& p = mesh.points[k];
    if (!std::isfinite(h[k])) return;  // a node no cell uses
    for (int a = 0; a < mesh.dim; ++a) {
      if (p[a] == lo[a] || p[a] == hi[a]) continue;  // stays on the boundary
      d[k][a] =
          o.amplitude * h[k] *
          detail::symmetric(o.seed, static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(i));
    }
  });
  return d;
}

std::vector<double> qualities(const io::MeshData& mesh) {
  std::vector<double> q(static_cast<std::size_t>(mesh.n_cells()));
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    q[static_cast<std::size_t>(i)] = detail::cell_quality(mesh, static_cast<std::size_t>(i));
  });
  return q;
}

}  // namespace

double min_scaled_jacobian(const io::MeshData& mesh) {
  const auto q = qualities(mesh);
  return q.empty() ? 1.0 : *std::min_element(q.begin(), q.end());
}

JitterResult jitter_nodes(io::MeshData& mesh, const JitterOptions& o) {
  if (!(o.amplitude >= 0 && o.amplitude < 0.5))
    throw OptionError("jitter amplitude must be in [0, 0.5), got " + std::to_string(o.amplitude));
  if (!(o.min_quality > 0 && o.min_quality <= 1))
    throw OptionError("jitter quality floor must be in (0, 1], got " +
                      std::to_string(o.min_quality));
  if (mesh.dim != 2 && mesh.dim != 3) throw OptionError("jitter needs quads or hexes");
  const double start_quality = min_scaled_jacobian(mesh);
  if (start_quality < o.min_quality)
    throw OptionError("the mesh is already below the jitter quality floor (" +
                      std::to_string(start_quality) + " < " + std::to_string(o.min_quality) + ")");
  const std::vector<Vec3> origin = mesh.points;
  std::vector<Vec3> d = displacements(mesh, o);
  std::vector<char> damped(d.size(), 0);
  for (std::size_t i = 0; i < d.size(); ++i) mesh.points[i] = origin[i] + d[i];

  // Halve (then reset) the displacements of the nodes of cells below the floor. Each reset
  // round zeroes at least one nonzero displacement, so the loop ends.
  const auto npc = static_cast<std::size_t>(mesh.nodes_per_cell());
  for (int round = 0;; ++round) {
    const auto q = qualities(mesh);
    std::vector<char> touched(d.size(), 0);
    bool any = false;
    for (std::size_t c = 0; c < q.size(); ++c) {
      if (q[c] >= o.min_quality) continue;
      any = true;
      for (std::size_t v = 0; v < npc; ++v) touched[mesh.cells[c * npc + v].idx()] = 1;
    }
    if (!any) break;
    const double factor = round < o.max_halvings ? 0.5 : 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!touched[i]) continue;
      d[i] *= factor;
      damped[i] = 1;
      mesh.points[i] = origin[i] + d[i];
    }
  }
  JitterResult res;
  for (std::size_t i = 0; i < d.size(); ++i) {
    res.moved_nodes += d[i].squaredNorm() > 0;
    res.damped_nodes += damped[i];
  }
  res.min_quality = min_scaled_jacobian(mesh);
  return res;
}

}  // namespace hexadapt::generate
