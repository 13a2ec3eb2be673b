#include "hexadapt/generate/jitter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hexadapt/core/error.h"
#include "hexadapt/core/parallel.h"
#include "hexadapt/mesh/cell_complex.h"
#include "random.h"

namespace hexadapt::generate {

namespace {

template <class M>
constexpr auto cell_edges() {
  if constexpr (M::dim == 2) {
    return std::array<std::array<int, 2>, 4>{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
  } else {
    return ref_hex::edges;
  }
}

template <class M>
std::vector<double> shortest_edges(const M& mesh) {
  std::vector<double> h(static_cast<std::size_t>(mesh.n_nodes()),
                        std::numeric_limits<double>::infinity());
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    const auto v = mesh.cell_nodes(c);
    for (const auto& e : cell_edges<M>()) {
      const NodeId a = v[static_cast<std::size_t>(e[0])], b = v[static_cast<std::size_t>(e[1])];
      const double len = (mesh.point(a) - mesh.point(b)).norm();
      h[a.idx()] = std::min(h[a.idx()], len);
      h[b.idx()] = std::min(h[b.idx()], len);
    }
  }
  return h;
}

template <class M>
std::vector<Vec3> displacements(const M& mesh, const JitterOptions& o) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    lo = lo.cwiseMin(mesh.point(n));
    hi = hi.cwiseMax(mesh.point(n));
  }
  const auto h = shortest_edges(mesh);
  std::vector<Vec3> d(static_cast<std::size_t>(mesh.n_nodes()), Vec3::Zero());
  parallel_for(mesh.n_nodes(), [&](std::int64_t i) {
    const Vec3 p = mesh.point(NodeId(i));
    for (int a = 0; a < M::dim; ++a) {
      if (p[a] == lo[a] || p[a] == hi[a]) continue;  // stays on the boundary
      d[static_cast<std::size_t>(i)][a] =
          o.amplitude * h[static_cast<std::size_t>(i)] *
          detail::symmetric(o.seed, static_cast<std::uint64_t>(a),
                            static_cast<std::uint64_t>(i));
    }
  });
  return d;
}

/// Cells below the floor, in increasing order.
template <class M>
std::vector<CellId> bad_cells(const M& mesh, double floor) {
  std::vector<char> bad(static_cast<std::size_t>(mesh.n_cells()), 0);
  parallel_for(mesh.n_cells(), [&](std::int64_t i) {
    bad[static_cast<std::size_t>(i)] = mesh.cell_quality(CellId(i)) < floor;
  });
  std::vector<CellId> out;
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (bad[c.idx()]) out.push_back(c);
  return out;
}

}  // namespace

template <class M>
JitterResult jitter_nodes(M& mesh, const JitterOptions& o) {
  if (!(o.amplitude >= 0 && o.amplitude < 0.5))
    throw OptionError("jitter amplitude must be in [0, 0.5), got " + std::to_string(o.amplitude));
  if (!(o.min_quality > 0 && o.min_quality <= 1))
    throw OptionError("jitter quality floor must be in (0, 1], got " +
                      std::to_string(o.min_quality));
  JitterResult res;
  const double start_quality = min_quality(mesh);
  if (start_quality < o.min_quality)
    throw OptionError("the mesh is already below the jitter quality floor (" +
                      std::to_string(start_quality) + " < " + std::to_string(o.min_quality) + ")");
  std::vector<Vec3> origin(static_cast<std::size_t>(mesh.n_nodes()));
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) origin[n.idx()] = mesh.point(n);
  std::vector<Vec3> d = displacements(mesh, o);
  std::vector<char> damped(d.size(), 0);
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) mesh.set_point(n, origin[n.idx()] + d[n.idx()]);

  // Halve (then reset) the displacements of the nodes of cells below the floor. Each reset
  // round zeroes at least one nonzero displacement, so the loop ends.
  for (int round = 0;; ++round) {
    const auto bad = bad_cells(mesh, o.min_quality);
    if (bad.empty()) break;
    const double factor = round < o.max_halvings ? 0.5 : 0.0;
    std::vector<char> touched(d.size(), 0);
    for (CellId c : bad)
      for (NodeId n : mesh.cell_nodes(c)) touched[n.idx()] = 1;
    for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
      if (!touched[n.idx()]) continue;
      d[n.idx()] *= factor;
      damped[n.idx()] = 1;
      mesh.set_point(n, origin[n.idx()] + d[n.idx()]);
    }
  }
  for (std::size_t i = 0; i < d.size(); ++i) {
    res.moved_nodes += d[i].squaredNorm() > 0;
    res.damped_nodes += damped[i];
  }
  res.min_quality = min_quality(mesh);
  return res;
}

template JitterResult jitter_nodes<QuadMesh>(QuadMesh&, const JitterOptions&);
template JitterResult jitter_nodes<HexMesh>(HexMesh&, const JitterOptions&);

}  // namespace hexadapt::generate
