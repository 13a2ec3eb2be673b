// Times an unstructured mesh spread over the ranks of an MPI job: every rank reads its share
// of a .pvtu's pieces and the pieces are merged (io::merge_rank_pieces), the dual graph is
// built, PT-Scotch cuts it into one part per rank, the cells move to their parts and get a
// ghost layer. Prints, per phase, the slowest rank's wall seconds, the CPU seconds of all
// ranks and the ranks' peak memory so far; then per rank its cells before and after the cut, its
// ghosts, the bytes it sent and its peak resident memory; and the faces the cut crosses.
//
//   mpirun -np N hexadapt_partition_bench FILE.pvtu
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>

#include "hexadapt/dist/dual_graph.h"
#include "hexadapt/dist/scotch_partition.h"
#include "hexadapt/io/vtk_collection.h"

namespace {

using namespace hexadapt;

double peak_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// Wall seconds of the slowest rank, and CPU seconds of all ranks, of f.
void phase(const dist::Communicator& comm, const char* name, const std::function<void()>& f) {
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  double max_wall = 0, total_cpu = 0;
  const std::vector<double> all = dist::all_gather_values(comm, std::vector<double>{wall, cpu});
  for (std::size_t r = 0; r + 1 < all.size(); r += 2) {
    max_wall = std::max(max_wall, all[r]);
    total_cpu += all[r + 1];
  }
  const std::vector<double> peaks = dist::all_gather_values(comm, std::vector<double>{peak_mib()});
  if (comm.rank() == 0)
    std::printf("  %-12s %8.3f s   cpu %8.3f s   peak so far %4.0f-%4.0f MiB per rank\n", name,
                max_wall, total_cpu, *std::min_element(peaks.begin(), peaks.end()),
                *std::max_element(peaks.begin(), peaks.end()));
}

std::vector<std::int64_t> cell_nodes(const io::MeshPart& part) {
  std::vector<std::int64_t> out;
  for (const NodeId v : part.data.cells) out.push_back(part.node_ids[v.idx()]);
  return out;
}

std::int64_t cut_faces(const dist::Communicator& comm, const dist::DistGraph& g,
                       const std::vector<int>& part) {
  const std::vector<int> all = dist::all_gather_values(comm, part);
  std::int64_t cut = 0;
  for (std::size_t e = 0; e < g.neighbours.size(); ++e) {
    const auto v = static_cast<std::size_t>(
        std::upper_bound(g.offsets.begin(), g.offsets.end(), static_cast<std::int64_t>(e)) -
        g.offsets.begin() - 1);
    cut += part[v] != all[static_cast<std::size_t>(g.neighbours[e])];
  }
  return dist::sum_in_rank_order(comm, cut) / 2;
}

void run(const dist::MpiCommunicator& comm, const std::string& path) {
  if (comm.rank() == 0) std::printf("%s on %d ranks\n", path.c_str(), comm.size());
  io::MeshPart read;
  phase(comm, "read+merge", [&] {
    read =
        io::merge_rank_pieces(comm, io::read_rank_pieces(path, {}, comm.rank(), comm.size()), {});
  });
  dist::DistGraph graph;
  phase(comm, "dual graph",
        [&] { graph = dist::dual_graph(comm, read.data.nodes_per_cell(), cell_nodes(read)); });
  std::vector<int> parts;
  phase(comm, "scotch", [&] { parts = dist::scotch_partition(comm, graph, comm.size()); });
  const std::int64_t read_cells = read.data.n_cells(), n_cells = read.n_cells,
                     n_nodes = read.n_nodes;
  io::MeshPart moved;
  phase(comm, "migrate", [&] { moved = io::migrate(comm, std::move(read), parts); });
  io::GhostedPart ghosted;
  phase(comm, "ghost layer", [&] { ghosted = io::with_ghost_layers(comm, moved); });
  const std::int64_t cut = cut_faces(comm, graph, parts);
  const std::vector<double> rows = dist::all_gather_values(
      comm, std::vector<double>{
                static_cast<double>(read_cells), static_cast<double>(moved.data.n_cells()),
                static_cast<double>(ghosted.part.data.n_cells() - ghosted.owned_cells),
                static_cast<double>(comm.bytes_sent()) / 1e6, peak_mib()});
  if (comm.rank() != 0) return;
  std::printf("  %lld cells, %lld nodes, %lld faces cut\n", static_cast<long long>(n_cells),
              static_cast<long long>(n_nodes), static_cast<long long>(cut));
  std::printf("  rank   cells read   cells owned   ghosts   MB sent   peak MiB\n");
  for (std::size_t r = 0; r * 5 < rows.size(); ++r)
    std::printf("  %4zu %12.0f %13.0f %8.0f %9.1f %10.0f\n", r, rows[r * 5], rows[r * 5 + 1],
                rows[r * 5 + 2], rows[r * 5 + 3], rows[r * 5 + 4]);
}

}  // namespace

int main(int argc, char** argv) {
  dist::MpiSession session(argc, argv);
  const dist::MpiCommunicator comm;
  if (argc != 2) {
    if (comm.rank() == 0) std::fprintf(stderr, "usage: mpirun -np N %s FILE.pvtu\n", argv[0]);
    return 1;
  }
  try {
    run(comm, argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rank %d: %s\n", comm.rank(), e.what());
    comm.abort(1);
  }
  return 0;
}
