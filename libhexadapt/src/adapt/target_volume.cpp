#include "hexadapt/adapt/target_volume.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "hexadapt/adapt/local_topology.h"
#include "hexadapt/quality/scaled_jacobian.h"

namespace hexadapt {

namespace {

double points_volume(const std::array<Vec3, 4>& p) {
  return quad_area(p);
}
double points_volume(const std::array<Vec3, 8>& p) {
  return hex_volume(p);
}

// A node the step moves: the material whose volume it serves and the direction that grows it.
struct Mover {
  NodeId node;
  int material = -1;
  Vec3 direction;
  double size = 0;  ///< local size: cube (2D: square) root of the mean volume of its cells
};

// The node's two materials when it is a plain interface node with exactly two around.
template <class M>
std::optional<std::pair<int, int>> two_materials(const M& mesh, const CellMaterials& material,
                                                 const Targets& targets, NodeId v) {
  if (!targets.has[v] || targets.interface[v].n_normals() != 1) return std::nullopt;
  int a = -1, b = -1;
  for (CellId c : mesh.node_cells(v)) {
    const int m = material[c];
    if (a < 0 || m == a) {
      a = m;
    } else if (b < 0 || m == b) {
      b = m;
    } else {
      return std::nullopt;
    }
  }
  if (b < 0) return std::nullopt;
  return std::pair{a, b};
}

// The nodes' positions during the offset: the targets where there are, else the grid's.
using Positions = IdVector<NodeId, Vec3>;

template <class M>
auto points_at(const M& mesh, const Positions& x, CellId c) {
  std::array<Vec3, M::nodes_per_cell> p;
  const auto nodes = mesh.cell_nodes(c);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = x[nodes[i]];
  return p;
}

// Volume of cell c with node v at p.
template <class M>
double volume_with(const M& mesh, const Positions& x, CellId c, NodeId v, const Vec3& p) {
  auto points = points_at(mesh, x, c);
  const auto nodes = mesh.cell_nodes(c);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (nodes[i] == v) points[i] = p;
  return points_volume(points);
}

// Rate at which the cells of the mover's material around it gain volume as it moves along
// its direction.
template <class M>
double growth_rate(const M& mesh, const Positions& x, const CellMaterials& material,
                   const Mover& m) {
  const Vec3 p = x[m.node];
  const double eps = 1e-3 * m.size;
  double rate = 0;
  for (CellId c : mesh.node_cells(m.node))
    if (material[c] == m.material)
      rate += (volume_with(mesh, x, c, m.node, p + eps * m.direction) -
               volume_with(mesh, x, c, m.node, p - eps * m.direction)) /
              (2 * eps);
  return rate;
}

template <class M>
std::vector<Mover> find_movers(const M& mesh, const CellMaterials& material,
                               const IdVector<NodeId, NodeConstraint>& boundary,
                               const Targets& targets, const std::vector<double>& volume) {
  std::vector<Mover> out;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    const auto ab = two_materials(mesh, material, targets, v);
    if (!ab) continue;
    const auto [a, b] = *ab;
    const Vec3 d = boundary[v].project(targets.interface[v].normal(0));
    if (d.norm() < 0.5) continue;
    double mean = 0;
    for (CellId c : mesh.node_cells(v)) mean += std::abs(mesh.cell_volume(c));
    mean /= static_cast<double>(mesh.node_cells(v).size());
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    out.push_back(
        {v, volume[ub] < volume[ua] ? b : a, d.normalized(), std::pow(mean, 1.0 / M::dim)});
  }
  return out;
}

}  // namespace

template <class M>
void conserve_target_volumes(const M& mesh, const Fractions& fractions,
                             const CellMaterials& material,
                             const IdVector<NodeId, NodeConstraint>& boundary, Targets& targets,
                             const TargetOptions& options, const VolumeParts* parts) {
  const bool runs = options.volume_offset == VolumeOffset::on ||
                    (options.volume_offset == VolumeOffset::automatic && M::dim == 3);
  if (!runs || options.volume_sweeps <= 0) return;
  const auto nm = static_cast<std::size_t>(fractions.n_materials());
  IdVector<CellId, double> grid_volume(static_cast<std::size_t>(mesh.n_cells()));
  for_each_item(grid_volume.size(), [&](std::int64_t i) {
    grid_volume[CellId(static_cast<index_t>(i))] =
        mesh.cell_volume(CellId(static_cast<index_t>(i)));
  });
  // On a part of a grid, the sums run over the cells and nodes it counts, then over the parts.
  const auto counts_cell = [&](CellId c) { return !parts || parts->counted_cells[c]; };
  const auto counts_node = [&](NodeId v) { return !parts || parts->counted_nodes[v]; };
  const auto add_up = [&](std::vector<double>& values) {
    if (parts) parts->add_up(values);
  };
  std::vector<double> input(nm, 0);
  for (CellId c : id_range<CellId>(mesh.n_cells()))
    if (counts_cell(c))
      for (std::size_t a = 0; a < nm; ++a)
        input[a] += fractions(c, static_cast<int>(a)) * grid_volume[c];
  add_up(input);
  std::vector<Mover> movers = find_movers(mesh, material, boundary, targets, input);
  std::vector<double> rate(nm, 0);  // of the whole grid: a part without movers still sums
  if (!parts && movers.empty()) return;
  Positions& x = targets.position;
  for (Mover& m : movers)
    if (growth_rate(mesh, x, material, m) < 0) m.direction = -m.direction;
  // Only the cells around movers change volume from sweep to sweep.
  std::vector<CellId> touched;
  for (const Mover& m : movers)
    for (CellId c : mesh.node_cells(m.node)) touched.push_back(c);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  // The volumes no sweep changes, less the input's. On a part, its own are added up first; on
  // the whole grid, the sums run in the order they always did (the same bits).
  std::vector<double> fixed(nm, 0);
  if (!parts)
    for (std::size_t a = 0; a < nm; ++a) fixed[a] = -input[a];
  for (CellId c : id_range<CellId>(mesh.n_cells())) {
    if (!counts_cell(c) || std::binary_search(touched.begin(), touched.end(), c)) continue;
    const auto nodes = mesh.cell_nodes(c);
    const bool on_grid =
        std::none_of(nodes.begin(), nodes.end(), [&](NodeId v) { return targets.has[v]; });
    fixed[static_cast<std::size_t>(material[c])] +=
        on_grid ? grid_volume[c] : points_volume(points_at(mesh, x, c));
  }
  if (parts) {
    add_up(fixed);
    for (std::size_t a = 0; a < nm; ++a) fixed[a] -= input[a];
  }
  // The rates hardly change over offsets this small: measured once.
  for (const Mover& m : movers)
    if (counts_node(m.node))
      rate[static_cast<std::size_t>(m.material)] += growth_rate(mesh, x, material, m);
  add_up(rate);
  std::vector<double> total(movers.size(), 0);
  for (int sweep = 0; sweep < options.volume_sweeps; ++sweep) {
    std::vector<double> error = parts ? std::vector<double>(nm, 0) : fixed;
    for (CellId c : touched)
      if (counts_cell(c))
        error[static_cast<std::size_t>(material[c])] += points_volume(points_at(mesh, x, c));
    if (parts) {
      add_up(error);
      for (std::size_t a = 0; a < nm; ++a) error[a] += fixed[a];
    }
    bool done = true;
    for (std::size_t a = 0; a < nm; ++a)
      if (rate[a] > 0 && std::abs(error[a]) > options.volume_tolerance * input[a]) done = false;
    if (done) break;
    for (std::size_t k = 0; k < movers.size(); ++k) {
      const auto a = static_cast<std::size_t>(movers[k].material);
      if (!(rate[a] > 0)) continue;
      const double bound = options.volume_max_shift * movers[k].size;
      const double next = std::clamp(total[k] - error[a] / rate[a], -bound, bound);
      x[movers[k].node] += (next - total[k]) * movers[k].direction;
      total[k] = next;
    }
  }
}

template void conserve_target_volumes<QuadMesh>(const QuadMesh&, const Fractions&,
                                                const IdVector<CellId, int>&,
                                                const IdVector<NodeId, NodeConstraint>&, Targets&,
                                                const TargetOptions&, const VolumeParts*);
template void conserve_target_volumes<HexMesh>(const HexMesh&, const Fractions&,
                                               const IdVector<CellId, int>&,
                                               const IdVector<NodeId, NodeConstraint>&, Targets&,
                                               const TargetOptions&, const VolumeParts*);

}  // namespace hexadapt
