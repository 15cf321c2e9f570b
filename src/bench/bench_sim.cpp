// Simulator throughput: 16 ships on the 3-DOF model with autopilots at dt = 0.1 s. The counter `rtf` is
// the real-time factor of the whole set (simulated seconds per wall second); the goal is >= 2000.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "asv_core/sim/autopilot.h"
#include "asv_core/sim/vessel_model.h"

namespace {

// The CMakeLists gives benchmarks no source-dir definition; CMake compiles with absolute paths, so the
// presets are found next to this file (src/bench/../config/vessels).
std::string presetDir() {
  const std::string here = __FILE__;
  return here.substr(0, here.find_last_of('/')) + "/../config/vessels";
}

void BM_Sim3dof16(benchmark::State& state) {
  using namespace asv;
  constexpr int kShips = 16;
  constexpr double kDt = 0.1, kSimSeconds = 600.0;
  const char* names[] = {"wu_asv_40m", "small_asv", "merchant"};
  std::vector<Mmg3DofModel> models;
  std::vector<Autopilot> pilots;
  for (int i = 0; i < kShips; ++i) {
    Mmg3DofModel m(loadVesselPreset(names[i % 3], presetDir()));
    pilots.emplace_back(tuneAutopilot(m), SpeedFeedForward::fromModel(m));
    models.push_back(m);
  }
  Environment env;
  env.wind_speed = 8.0;
  env.wind_direction = degToRad(45.0);
  env.wave_height = 1.0;
  env.wave_direction = degToRad(30.0);
  env.wave_length = 40.0;
  const int steps = static_cast<int>(kSimSeconds / kDt);
  for (auto _ : state) {
    for (int i = 0; i < kShips; ++i) {
      VesselState s;
      s.x = 1000.0 * i;
      s.u = models[i].params().steady_speed;
      models[i].setState(s);
      pilots[i].reset();
    }
    for (int k = 0; k < steps; ++k) {
      const int leg = k / 1000;  // a new course every 1000 steps (100 s) keeps the rudders working
      if (k % 1000 == 0)
        for (int i = 0; i < kShips; ++i)
          pilots[i].setCourseSpeed(degToRad(37.0 * (leg + i)), models[i].params().steady_speed);
      for (int i = 0; i < kShips; ++i)
        models[i].step(pilots[i].update(models[i].state(), kDt), env, kDt);
    }
    benchmark::DoNotOptimize(models.front().state());
  }
  state.counters["rtf"] =
      benchmark::Counter(kSimSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Sim3dof16)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
