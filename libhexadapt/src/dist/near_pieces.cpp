// near_other_pieces of dist::merge_pieces: the pieces' bounding boxes (every rank's part of
// each), and for each point the test of its tolerance box against the boxes of the other
// pieces that come near its own piece's.
#include <algorithm>
#include <array>
#include <limits>

#include "hexadapt/dist/merge_pieces.h"
#include "hexadapt/dist/routing.h"

namespace hexadapt::dist {

namespace {

// A piece's bounding box (of its finite points), over every rank holding some of it.
struct PieceBox {
  std::int64_t piece;
  std::array<double, 3> lo, hi;

  bool touches(const Vec3& p, double margin) const {
    for (std::size_t a = 0; a < 3; ++a)
      if (!(p[static_cast<int>(a)] + margin >= lo[a] && p[static_cast<int>(a)] - margin <= hi[a]))
        return false;
    return true;
  }
};

std::vector<PieceBox> piece_boxes(const Communicator& comm, const PiecesPart& part) {
  std::vector<PieceBox> mine;
  for (std::size_t q = 0; q < part.points.size(); ++q) {
    const Vec3& p = part.points[q];
    if (!p.allFinite()) continue;
    if (mine.empty() || mine.back().piece != part.point_piece[q])
      mine.push_back({part.point_piece[q], {p[0], p[1], p[2]}, {p[0], p[1], p[2]}});
    for (std::size_t a = 0; a < 3; ++a) {
      mine.back().lo[a] = std::min(mine.back().lo[a], p[static_cast<int>(a)]);
      mine.back().hi[a] = std::max(mine.back().hi[a], p[static_cast<int>(a)]);
    }
  }
  std::vector<PieceBox> all = all_gather_values(comm, mine);
  std::stable_sort(all.begin(), all.end(),
                   [](const PieceBox& a, const PieceBox& b) { return a.piece < b.piece; });
  std::vector<PieceBox> merged;
  for (const PieceBox& b : all) {
    if (merged.empty() || merged.back().piece != b.piece) {
      merged.push_back(b);
      continue;
    }
    for (std::size_t a = 0; a < 3; ++a) {
      merged.back().lo[a] = std::min(merged.back().lo[a], b.lo[a]);
      merged.back().hi[a] = std::max(merged.back().hi[a], b.hi[a]);
    }
  }
  return merged;
}

// The other pieces whose box comes within twice the largest tolerance of piece `piece`'s
// box: the only ones its points can come near.
std::vector<const PieceBox*> near_pieces(const std::vector<PieceBox>& boxes, std::int64_t piece,
                                         double max_tolerance) {
  const auto own = std::lower_bound(boxes.begin(), boxes.end(), piece,
                                    [](const PieceBox& b, std::int64_t p) { return b.piece < p; });
  std::vector<const PieceBox*> out;
  if (own == boxes.end() || own->piece != piece) return out;
  for (const PieceBox& b : boxes) {
    if (b.piece == piece) continue;
    bool apart = false;
    for (std::size_t a = 0; a < 3; ++a)
      apart = apart || b.lo[a] > own->hi[a] + 2 * max_tolerance ||
              b.hi[a] < own->lo[a] - 2 * max_tolerance;
    if (!apart) out.push_back(&b);
  }
  return out;
}

}  // namespace

std::vector<char> near_other_pieces(const Communicator& comm, const PiecesPart& part) {
  const std::vector<PieceBox> boxes = piece_boxes(comm, part);
  double max_tolerance = 0;
  for (const double t : part.tolerance) max_tolerance = std::max(max_tolerance, t);
  for (const double t : all_gather_values(comm, std::vector<double>{max_tolerance}))
    max_tolerance = std::max(max_tolerance, t);
  std::vector<char> near(part.points.size(), 0);
  std::vector<const PieceBox*> others;
  for (std::size_t q = 0; q < near.size(); ++q) {
    if (q == 0 || part.point_piece[q] != part.point_piece[q - 1])
      others = near_pieces(boxes, part.point_piece[q], max_tolerance);
    near[q] = std::any_of(others.begin(), others.end(), [&](const PieceBox* o) {
      return o->touches(part.points[q], part.tolerance[q]);
    });
  }
  return near;
}

}  // namespace hexadapt::dist
