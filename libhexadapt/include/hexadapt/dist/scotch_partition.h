// Cutting a graph spread over the ranks into parts with PT-Scotch (Debian's libptscotch):
// what spreads an unstructured mesh's cells over the ranks. This header belongs to the
// library hexadapt::mpi (HEXADAPT_MPI), as the communicator over MPI does.
#pragma once

#include <vector>

#include "hexadapt/dist/dual_graph.h"
#include "hexadapt/dist/mpi_communicator.h"

namespace hexadapt::dist {

/// The part (0 .. parts - 1) of each of this rank's vertices of `graph`: few edges between
/// parts, the parts' vertex counts (with graph.weights, their weights) within 5 % of each
/// other. Deterministic: the same graph on
/// the same number of ranks gives the same parts in every run (Scotch's deterministic mode
/// and fixed random seed). Throws OptionError when parts < 1, ResourceError when the graph
/// has 2^31 vertices or arcs or more (the 32-bit numbers of Debian's default Scotch),
/// InternalError when Scotch fails. Every rank calls it.
std::vector<int> scotch_partition(const MpiCommunicator& comm, const DistGraph& graph, int parts);

}  // namespace hexadapt::dist
