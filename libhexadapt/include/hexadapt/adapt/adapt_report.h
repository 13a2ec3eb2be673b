// What an adapt run reports (field list and meaning: docs/reports.md): the figures that add up
// over the parts adapted on several ranks, their sum in rank order, and the report as JSON.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hexadapt/adapt/adapt.h"

namespace hexadapt {

/// The interface node farthest from its surface.
struct FarthestNode {
  bool valid = false;
  std::int64_t node = -1;  ///< its id in the output mesh; -1 when no single mesh names it
  double distance = 0;     ///< its surface distance
  double local_size = 0;   ///< the mean local size of its cells
  Vec3 position = Vec3::Zero();
};

/// The figures of a run (or of one rank's part of it, over the nodes that rank counts) whose
/// sum over the ranks is the run's: counts and sums add up, least qualities take the least,
/// loops and seconds the most, the farthest node the farthest.
struct AdaptFigures {
  index_t cells_in = 0, cells = 0, nodes = 0;
  index_t interface_nodes = 0, reached = 0, near_interface = 0;
  index_t blocked = 0, frozen_blocked = 0;
  index_t below_threshold = 0, inverted = 0, below_min_edge = 0;
  double dist_init = 0, dist_final = 0, surface_dist_init = 0, surface_dist_final = 0;
  double min_quality = std::numeric_limits<double>::infinity();
  double min_edge_ratio = std::numeric_limits<double>::infinity();
  double input_min_quality = std::numeric_limits<double>::infinity();
  int loops = 0;
  double seconds = 0;
  FarthestNode farthest;

  /// Cells failing the threshold or the size criterion.
  index_t failing() const { return below_threshold + below_min_edge; }
};

/// The figures of `r`, a run on `cells_in` input cells, as it counted them.
template <class M>
AdaptFigures adapt_figures(const AdaptResult<M>& r, index_t cells_in);

/// The figures of a rank's part `r` of a run: its nodes counted where `counted` is set (each
/// node of the whole mesh by one rank), its `cells_in` own input cells, its `seconds`.
template <class M>
AdaptFigures adapt_figures(const AdaptResult<M>& r, const IdVector<NodeId, char>& counted,
                           index_t cells_in, double seconds);

/// The run's figures from its parts', in the order given (rank order).
AdaptFigures summed(const std::vector<AdaptFigures>& parts);

/// The figures as the report's fields (docs/reports.md), a JSON object.
std::string adapt_figures_json(const AdaptFigures& f);

/// The cells failing a criterion as a JSON array: which one, where, by how much.
std::string failures_json(const std::vector<CellFailure>& failures, double threshold);

/// The whole report of a run on one process on `cells_in` input cells (the figures, then each
/// step's), a JSON object.
template <class M>
std::string adapt_result_json(const AdaptResult<M>& r, index_t cells_in, double threshold);

}  // namespace hexadapt
