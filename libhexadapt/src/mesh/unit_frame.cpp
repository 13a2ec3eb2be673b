#include "hexadapt/mesh/unit_frame.h"

#include <cstdlib>
#include <limits>

#include "hexadapt/mesh/hex_mesh.h"
#include "hexadapt/mesh/quad_mesh.h"

namespace hexadapt {

namespace {

UnitFrame frame_of_box(const Vec3& low, const Vec3& high) {
  UnitFrame f;
  if (!low.allFinite() || !high.allFinite()) return f;
  // The largest extent, not the diagonal's norm: that one squares the extents first.
  const double size = (high - low).cwiseAbs().maxCoeff();
  if (!(size > 0)) return f;
  int e = 0;
  std::frexp(size, &e);  // size = m 2^e, m in [0.5, 1)
  f.exponent = e - 1;    // size 2^-(e-1) in [1, 2)
  const double far = low.cwiseAbs().maxCoeff();
  if (far > size) f.origin = low;
  return f;
}

template <class M, class Move>
M moved(const M& mesh, const Move& move) {
  M out = mesh;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) out.set_point(v, move(mesh.point(v)));
  return out;
}

}  // namespace

UnitFrame unit_frame(const std::vector<Vec3>& points) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const Vec3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return frame_of_box(low, high);
}

template <class M>
UnitFrame unit_frame(const M& mesh) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (NodeId v : id_range<NodeId>(mesh.n_nodes())) {
    low = low.cwiseMin(mesh.point(v));
    high = high.cwiseMax(mesh.point(v));
  }
  return frame_of_box(low, high);
}

UnitFrame far_unit_frame(const std::vector<Vec3>& points) {
  const UnitFrame f = unit_frame(points);
  return std::abs(f.exponent) > 64 ? f : UnitFrame{};
}

template <class M>
UnitFrame far_unit_frame(const M& mesh) {
  const UnitFrame f = unit_frame(mesh);
  return std::abs(f.exponent) > 64 ? f : UnitFrame{};
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
template QuadMesh to_local(const QuadMesh&, const UnitFrame&);
template HexMesh to_local(const HexMesh&, const UnitFrame&);
template QuadMesh to_world(const QuadMesh&, const UnitFrame&);
template HexMesh to_world(const HexMesh&, const UnitFrame&);

}  // namespace hexadapt
