// Progress reporting of the measure library (imprint, quality report) and of the blocked
// parallel loop under them: one phase name, fractions that never decrease and end at
// exactly 1, from the calling thread, and results identical to a run without a callback.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <thread>
#include <vector>

#include "hexadapt/core/parallel.h"
#include "hexadapt/core/parallel_progress.h"
#include "hexadapt/io/mesh_data.h"
#include "hexadapt/measure/imprint.h"
#include "hexadapt/measure/quality_report.h"
#include "hexadapt/mesh/structured.h"

namespace hexadapt {
namespace {

struct Recorder {
  std::vector<std::string> phases;
  std::vector<double> fractions;
  std::thread::id caller = std::this_thread::get_id();
  bool other_thread = false;
  Progress callback() {
    return [this](std::string_view phase, double f) {
      phases.emplace_back(phase);
      fractions.push_back(f);
      other_thread = other_thread || std::this_thread::get_id() != caller;
    };
  }
};

void expect_monotone_to_one(const Recorder& r, const std::string& phase, std::size_t min_calls) {
  ASSERT_GE(r.fractions.size(), min_calls);
  for (const auto& p : r.phases) EXPECT_EQ(p, phase);
  EXPECT_GE(r.fractions.front(), 0.0);
  for (std::size_t i = 1; i < r.fractions.size(); ++i)
    EXPECT_GE(r.fractions[i], r.fractions[i - 1]) << "call " << i;
  EXPECT_EQ(r.fractions.back(), 1.0);
  EXPECT_FALSE(r.other_thread) << "progress must be reported from the calling thread";
}

io::MeshData jittered_hexes(int n, unsigned seed) {
  io::MeshData d = io::from_mesh(make_hex_grid(n, n, n, Vec3::Zero(), Vec3(1, 1, 1)));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (Vec3& p : d.points) p += Vec3(u(rng), u(rng), u(rng));
  return d;
}

TEST(ParallelProgress, VisitsEveryItemOnceAndEndsAtOne) {
  for (std::int64_t n : {0, 1, 255, 256, 1000, 25601}) {
    Recorder r;
    std::vector<int> seen(static_cast<std::size_t>(n), 0);
    parallel_for_progress(n, r.callback(), "loop",
                          [&](std::int64_t i) { ++seen[static_cast<std::size_t>(i)]; });
    for (int s : seen) ASSERT_EQ(s, 1) << "n = " << n;
    expect_monotone_to_one(r, "loop", 1);
    EXPECT_LE(r.fractions.size(), 102u) << "about a hundred updates at most";
  }
}

TEST(ParallelProgress, SubRangeEndsExactlyAtItsEnd) {
  Recorder r;
  parallel_for_progress(
      10000, r.callback(), "part", [](std::int64_t) {}, 0.3, 0.7);
  ASSERT_FALSE(r.fractions.empty());
  EXPECT_GT(r.fractions.front(), 0.3);
  EXPECT_EQ(r.fractions.back(), 0.7);
  for (std::size_t i = 1; i < r.fractions.size(); ++i)
    EXPECT_GT(r.fractions[i], r.fractions[i - 1]);
}

TEST(MeasureProgress, ImprintReportsMonotoneFractionsAndSameResult) {
  const io::MeshData in = jittered_hexes(7, 1), out = jittered_hexes(7, 2);
  const CellMaterials material(static_cast<std::size_t>(out.n_cells()), 0);
  set_threads(2);
  Recorder r;
  ImprintOptions with;
  with.progress = r.callback();
  const Imprint a = imprint(in, out, material, 1, with);
  const Imprint b = imprint(in, out, material, 1);
  set_threads(0);
  // 343 cells: blocks of 256, so at least two calls.
  expect_monotone_to_one(r, "imprint", 2);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.cell_volume, b.cell_volume);
}

TEST(MeasureProgress, QualityReportReportsMonotoneFractions) {
  const io::MeshData mesh = jittered_hexes(12, 3);
  Recorder r;
  QualityReportOptions options;
  options.progress = r.callback();
  const QualityReport with = quality_report(mesh, options);
  const QualityReport without = quality_report(mesh);
  expect_monotone_to_one(r, "quality", 3);
  EXPECT_EQ(with.scaled_jacobian.min, without.scaled_jacobian.min);
  EXPECT_EQ(with.histogram.counts, without.histogram.counts);
}

}  // namespace
}  // namespace hexadapt
