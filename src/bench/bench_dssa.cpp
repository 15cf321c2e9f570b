// One full DSSA+ decision (all rounds of Fig. 2 to quiescence) for the 16 ships of the paper's Sec. 5.2,
// at the first time step and in the thick of the crossing. Goal: at most 5 ms on one core.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "asv_core/papers/dssa_experiments.h"
#include "asv_core/planning/dssa/dssa.h"

namespace {

using namespace asv;

// The 16 ships moved `t` seconds straight along their tracks (t = 8: 340 m apart at most, all
// neighbours of each other, head-on and crossing conflicts everywhere).
void bmDssaPlus16(benchmark::State& state) {
  const DssaScenario sc = dssaSixteenShipScenario();
  const DssaConfig config = DssaConfig::preset("dssa_plus_sc");
  const double t = static_cast<double>(state.range(0));
  std::vector<ShipState> ships;
  for (const auto& s : sc.ships) {
    ShipState st;
    st.course = trueBearing(s.start, s.goal);
    st.heading = st.course;
    st.speed = s.speeds.ref;
    st.position = s.start + st.velocity() * t;
    ships.push_back(st);
  }
  std::vector<DssaAgent> agents;
  for (std::size_t i = 0; i < sc.ships.size(); ++i)
    agents.emplace_back(static_cast<int>(i), config, sc.ships[i].speeds);
  const DssaExchange exchange(config);
  uint64_t seed = 1;
  long rounds = 0, quiescent = 0;
  for (auto _ : state) {
    std::vector<std::mt19937_64> rngs;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      agents[i].setOwn(ships[i], sc.ships[i].goal, t);
      rngs.emplace_back(dssaAgentSeed(seed, static_cast<int>(i)));
    }
    const DssaExchange::Result r = exchange.run(agents, rngs);
    benchmark::DoNotOptimize(agents[0].intention().course);
    rounds += r.rounds;
    quiescent += r.quiescent ? 1 : 0;
    ++seed;
  }
  state.counters["rounds"] =
      benchmark::Counter(static_cast<double>(rounds), benchmark::Counter::kAvgIterations);
  state.counters["quiescent"] =
      benchmark::Counter(static_cast<double>(quiescent), benchmark::Counter::kAvgIterations);
}

}  // namespace

BENCHMARK(bmDssaPlus16)->Name("BM_DssaPlus16")->Arg(0)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
