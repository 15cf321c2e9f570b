// BM_LandQuery*: clearance queries against a coastline of 10,000 vertices through ObstacleIndex (an
// R-tree of edges) beside the linear scan it replaces. Goal: <= 2 us per query on one core.
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>

#include "asv_core/common/obstacle_index.h"

namespace {

// A ragged coast: a 30 km wide star-shaped island of n vertices whose radius wanders (random walk),
// with queries at sea within 2 km of it, legs 500 m long.
struct Coast {
  asv::Polygon polygon;
  std::vector<Eigen::Vector2d> a, b;
};

const Coast& coast() {
  static const Coast c = [] {
    Coast c;
    std::mt19937 rng(1);
    std::normal_distribution<double> step(0.0, 40.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 10000;
    double r = 15000.0;
    for (int i = 0; i < n; ++i) {
      r = std::clamp(r + step(rng), 13000.0, 17000.0);
      const double ang = 2 * M_PI * i / n;
      c.polygon.emplace_back(r * std::cos(ang), r * std::sin(ang));
    }
    for (int k = 0; k < 4096; ++k) {
      const double ang = 2 * M_PI * u(rng), rr = 17000.0 + 2000.0 * u(rng), h = 2 * M_PI * u(rng);
      c.a.emplace_back(rr * std::cos(ang), rr * std::sin(ang));
      c.b.push_back(c.a.back() + 500.0 * Eigen::Vector2d(std::cos(h), std::sin(h)));
    }
    return c;
  }();
  return c;
}

void BM_LandQueryIndexSegment(benchmark::State& state) {
  const Coast& c = coast();
  const asv::ObstacleIndex idx({c.polygon});
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(idx.distance(c.a[k], c.b[k]));
    k = (k + 1) % c.a.size();
  }
  state.counters["vertices"] = static_cast<double>(c.polygon.size());
}
BENCHMARK(BM_LandQueryIndexSegment)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

void BM_LandQueryIndexInside(benchmark::State& state) {
  const Coast& c = coast();
  const asv::ObstacleIndex idx({c.polygon});
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(idx.inside(c.a[k]));
    k = (k + 1) % c.a.size();
  }
}
BENCHMARK(BM_LandQueryIndexInside)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LandQueryLinearScan(benchmark::State& state) {
  const Coast& c = coast();
  size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(asv::segmentObstacleDistance(c.polygon, c.a[k], c.b[k]));
    k = (k + 1) % c.a.size();
  }
}
BENCHMARK(BM_LandQueryLinearScan)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LandIndexBuild(benchmark::State& state) {
  const Coast& c = coast();
  for (auto _ : state) {
    const asv::ObstacleIndex idx({c.polygon});
    benchmark::DoNotOptimize(idx.edges());
  }
}
BENCHMARK(BM_LandIndexBuild)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
