// BM_RiskAssess/N: one full risk assessment (CPA + CRI + encounter classification + compliance
// flag) of N targets round the own ship. Goal (issue 2): <= 0.5 ms for N = 1000 on one core.
#include <benchmark/benchmark.h>

#include <random>

#include "asv_core/risk/risk_assessment.h"

namespace {

std::vector<asv::ShipState> makeTargets(int n) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-20000.0, 20000.0), course(0.0, asv::kTwoPi), speed(0.0, 12.0);
  std::vector<asv::ShipState> out(n);
  for (int i = 0; i < n; ++i) {
    out[i].id = "t" + std::to_string(i);
    out[i].position = {pos(rng), pos(rng)};
    out[i].course = out[i].heading = course(rng);
    out[i].speed = speed(rng);
  }
  return out;
}

void BM_RiskAssess(benchmark::State& state) {
  const auto targets = makeTargets(static_cast<int>(state.range(0)));
  asv::ShipState own;
  own.id = "own";
  own.speed = 6.0;
  asv::RiskAssessor assessor;
  for (auto _ : state) {
    auto risks = assessor.assessAll(own, targets, false);
    benchmark::DoNotOptimize(risks.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RiskAssess)->Arg(1)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
