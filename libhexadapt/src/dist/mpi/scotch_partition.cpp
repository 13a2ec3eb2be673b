// dist::scotch_partition: the graph handed to PT-Scotch as its distributed graph (vertex
// ranges in rank order, global neighbour ids), bound to a context that makes Scotch's
// choices reproducible, and cut with the default mapping strategy.
#include "hexadapt/dist/scotch_partition.h"

// ptscotch.h needs mpi.h (MPI_Comm) before it.
#include <mpi.h>
#include <scotch/ptscotch.h>

#include <cstdint>
#include <limits>

#include "hexadapt/core/error.h"

namespace hexadapt::dist {

namespace {

constexpr double imbalance = 0.05;

void check_scotch(int status, const char* what) {
  if (status != 0) throw InternalError(std::string("PT-Scotch: ") + what + " failed");
}

SCOTCH_Num to_num(std::int64_t v) {
  if (v > std::numeric_limits<SCOTCH_Num>::max())
    throw ResourceError(
        "the graph to partition has " + std::to_string(v) +
        " vertices, arcs or units of vertex weight: more than the 32-bit numbers of "
        "Debian's Scotch hold");
  return static_cast<SCOTCH_Num>(v);
}

// The Scotch objects of one partition, released in the reverse order of their making.
struct Scotch {
  SCOTCH_Dgraph built{}, bound{};
  SCOTCH_Context context{};
  SCOTCH_Strat strategy{};
  bool have_built = false, have_bound = false, have_context = false, have_strategy = false;
  ~Scotch() {
    if (have_strategy) SCOTCH_stratExit(&strategy);
    if (have_bound) SCOTCH_dgraphExit(&bound);
    if (have_context) SCOTCH_contextExit(&context);
    if (have_built) SCOTCH_dgraphExit(&built);
  }
};

}  // namespace

std::vector<int> scotch_partition(const MpiCommunicator& comm, const DistGraph& graph, int parts) {
  if (parts < 1) throw OptionError("partition into " + std::to_string(parts) + " parts");
  const auto n = static_cast<std::size_t>(graph.n_vertices());
  // Sizes first, on every rank, so that every rank refuses a graph too large together.
  if (!graph.weights.empty() && graph.weights.size() != n)
    throw InternalError(std::to_string(graph.weights.size()) + " weights for " + std::to_string(n) +
                        " vertices");
  std::int64_t weight = 0;
  for (const std::int64_t w : graph.weights) {
    if (w < 1) throw InternalError("a vertex weight " + std::to_string(w) + " below 1");
    weight += w;
  }
  const std::vector<std::int64_t> sizes = all_gather_values(
      comm, std::vector<std::int64_t>{graph.n_vertices(),
                                      static_cast<std::int64_t>(graph.neighbours.size()), weight,
                                      graph.weights.empty() ? 0 : 1});
  std::int64_t vertices = 0, arcs = 0, weights = 0;
  bool weighted = false;  // Scotch takes weights from every rank or from none
  for (std::size_t r = 0; r + 3 < sizes.size(); r += 4) {
    vertices += sizes[r];
    arcs += sizes[r + 1];
    weights += sizes[r + 2];
    weighted = weighted || sizes[r + 3] != 0;
  }
  if (weighted && graph.weights.empty() && n > 0)
    throw InternalError("vertex weights on some ranks only");
  to_num(vertices);
  to_num(arcs);
  to_num(weights);
  if (parts == 1) return std::vector<int>(n, 0);
  std::vector<SCOTCH_Num> offsets(graph.offsets.begin(), graph.offsets.end());
  std::vector<SCOTCH_Num> neighbours(graph.neighbours.begin(), graph.neighbours.end());
  if (neighbours.empty()) neighbours.push_back(0);  // Scotch wants an array even when empty
  std::vector<SCOTCH_Num> vertex_weights(graph.weights.begin(), graph.weights.end());
  if (vertex_weights.empty()) vertex_weights.push_back(1);  // a rank without vertices
  Scotch s;
  check_scotch(SCOTCH_dgraphInit(&s.built, MPI_COMM_WORLD), "graph init");
  s.have_built = true;
  const auto local = static_cast<SCOTCH_Num>(n);
  const auto local_arcs = static_cast<SCOTCH_Num>(graph.neighbours.size());
  check_scotch(SCOTCH_dgraphBuild(&s.built, 0, local, local, offsets.data(), offsets.data() + 1,
                                  weighted ? vertex_weights.data() : nullptr, nullptr, local_arcs,
                                  local_arcs, neighbours.data(), nullptr, nullptr),
               "graph build");
  check_scotch(SCOTCH_contextInit(&s.context), "context init");
  s.have_context = true;
  check_scotch(SCOTCH_contextOptionSetNum(&s.context, SCOTCH_OPTIONNUMDETERMINISTIC, 1),
               "deterministic option");
  check_scotch(SCOTCH_contextOptionSetNum(&s.context, SCOTCH_OPTIONNUMRANDOMFIXEDSEED, 1),
               "seed option");
  // A random generator of the context's own, seeded the same every time (not Scotch's global
  // one, which earlier partitions of this process have advanced).
  check_scotch(SCOTCH_contextRandomClone(&s.context), "random generator");
  SCOTCH_contextRandomSeed(&s.context, 1);
  check_scotch(SCOTCH_dgraphInit(&s.bound, MPI_COMM_WORLD), "bound graph init");
  s.have_bound = true;
  check_scotch(SCOTCH_contextBindDgraph(&s.context, &s.built, &s.bound), "context binding");
  check_scotch(SCOTCH_stratInit(&s.strategy), "strategy init");
  s.have_strategy = true;
  check_scotch(
      SCOTCH_stratDgraphMapBuild(&s.strategy, SCOTCH_STRATDEFAULT, comm.size(), parts, imbalance),
      "strategy");
  std::vector<SCOTCH_Num> part(std::max<std::size_t>(n, 1));
  check_scotch(SCOTCH_dgraphPart(&s.bound, parts, &s.strategy, part.data()), "partition");
  return std::vector<int>(part.begin(), part.begin() + static_cast<std::ptrdiff_t>(n));
}

std::vector<int> MpiCommunicator::parts_of(const DistGraph& graph) const {
  return scotch_partition(*this, graph, size());
}

}  // namespace hexadapt::dist
