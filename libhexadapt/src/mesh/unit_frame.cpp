#include "hexadapt/mesh/unit_frame.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

namespace {

// The frame of the n points point(0), ..., point(n - 1); the identity when one is not finite.
template <class Point>
UnitFrame frame_of(std::size_t n, const Point& point) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (std::size_t i = 0; i < n; ++i) {
    low = low.cwiseMin(point(i));
    high = high.cwiseMax(point(i));
  }
  UnitFrame f;
  if (!low.allFinite() || !high.allFinite()) return f;
  // The largest extent, not the diagonal's norm: that one squares the extents first.
  const double size = (high - low).cwiseAbs().maxCoeff();
  if (!(size > 0)) return f;
  f.exponent = unit_exponent(size);
  if (low.cwiseAbs().maxCoeff() > size) f.origin = low;
  return f;
}

UnitFrame only_far(const UnitFrame& f) {
  return std::abs(f.exponent) > 64 ? f : UnitFrame{};
}

template <class M, class Move>
M moved(const M& mesh, const Move& move) {
  M out = mesh;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) out.set_point(v, move(mesh.point(v)));
  return out;
}

}  // namespace

int unit_exponent(double size) {
  if (!(size > 0) || !std::isfinite(size)) return 0;
  int e = 0;
  std::frexp(size, &e);  // size = m 2^e, m in [0.5, 1)
  return e - 1;          // size 2^-(e-1) in [1, 2)
}

UnitFrame unit_frame(const std::vector<Vec3>& points) {
  return frame_of(points.size(), [&](std::size_t i) { return points[i]; });
}

template <class M>
UnitFrame unit_frame(const M& mesh) {
  return frame_of(static_cast<std::size_t>(mesh.n_nodes()),
                  [&](std::size_t i) { return mesh.point(NodeId(static_cast<index_t>(i))); });
}

UnitFrame far_unit_frame(const std::vector<Vec3>& points) {
  return only_far(unit_frame(points));
}

template <class M>
UnitFrame far_unit_frame(const M& mesh) {
  return only_far(unit_frame(mesh));
}

namespace {

// The low and high corners of every rank's points, in rank order.
template <class M>
std::vector<Vec3> rank_boxes(const M& mesh, const dist::Communicator& comm) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (NodeId n : id_range<NodeId>(mesh.n_nodes())) {
    low = low.cwiseMin(mesh.point(n));
    high = high.cwiseMax(mesh.point(n));
  }
  std::vector<double> box;
  for (const Vec3& p : {low, high}) box.insert(box.end(), p.data(), p.data() + 3);
  const std::vector<double> all = dist::all_gather_values(comm, box);
  std::vector<Vec3> corners;
  for (std::size_t i = 0; i + 2 < all.size(); i += 3)
    corners.emplace_back(all[i], all[i + 1], all[i + 2]);
  return corners;
}

}  // namespace

template <class M>
UnitFrame unit_frame(const M& mesh, const dist::Communicator& comm) {
  return comm.size() == 1 ? unit_frame(mesh) : unit_frame(rank_boxes(mesh, comm));
}

template <class M>
UnitFrame far_unit_frame(const M& mesh, const dist::Communicator& comm) {
  return comm.size() == 1 ? far_unit_frame(mesh) : far_unit_frame(rank_boxes(mesh, comm));
}

template <class M>
M to_local(const M& mesh, const UnitFrame& frame) {
  if (frame.is_identity()) return mesh;
  return moved(mesh, [&](const Vec3& p) { return frame.to_local(p); });
}

template <class M>
M to_world(const M& mesh, const UnitFrame& frame) {
  if (frame.is_identity()) return mesh;
  return moved(mesh, [&](const Vec3& p) { return frame.to_world(p); });
}

template UnitFrame unit_frame(const QuadMesh&);
template UnitFrame unit_frame(const HexMesh&);
template UnitFrame far_unit_frame(const QuadMesh&);
template UnitFrame far_unit_frame(const HexMesh&);
template UnitFrame unit_frame(const QuadMesh&, const dist::Communicator&);
template UnitFrame unit_frame(const HexMesh&, const dist::Communicator&);
template UnitFrame far_unit_frame(const QuadMesh&, const dist::Communicator&);
template UnitFrame far_unit_frame(const HexMesh&, const dist::Communicator&);
template QuadMesh to_local(const QuadMesh&, const UnitFrame&);
template HexMesh to_local(const HexMesh&, const UnitFrame&);
template QuadMesh to_world(const QuadMesh&, const UnitFrame&);
template HexMesh to_world(const HexMesh&, const UnitFrame&);

}  // namespace hexadapt
