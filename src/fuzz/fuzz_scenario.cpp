// libFuzzer target for the scenario loader, asv::parseScenario(yaml_text, source). Not built by CMake;
// scripts/fuzz_smoke.sh builds and runs it (seeded with the asv_bringup/scenarios/*.yaml files under
// 2.5 KB), or by hand from the repository root:
//
//   clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -I src/include \
//     -I /usr/include/eigen3 src/fuzz/fuzz_scenario.cpp src/lib/world/scenario.cpp \
//     src/lib/world/obstacles.cpp src/lib/common/obstacle_index.cpp src/lib/common/geodesy.cpp \
//     src/lib/common/param_map.cpp \
//     src/lib/common/geometry.cpp src/lib/risk/domain.cpp -lyaml-cpp -lGeographicLib -o fuzz_scenario
//   mkdir -p corpus && cp asv_bringup/scenarios/*.yaml corpus/
//   ./fuzz_scenario corpus -dict=src/fuzz/scenario.dict -max_total_time=20
//
// Contract checked: any input either yields a Scenario or throws asv::ScenarioError with a message, as
// scenario.h documents (another std::exception, an exception of another type, a crash, a sanitizer
// report or a hang is a finding). For a scenario it accepts: every number finite and in the documented
// range, ship names unique, no two ships starting closer than the overlap limit, obstacles with 3+
// finite vertices.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>

#include "asv_core/common/geodesy.h"
#include "asv_core/world/scenario.h"

namespace {

bool finite(const Eigen::Vector2d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

void check(bool ok) {
  if (!ok)
    __builtin_trap();
}

void checkShip(const asv::ScenarioShip& s, bool own) {
  check(!s.name.empty() && s.name.find_first_of(" /\t") == std::string::npos);
  check(s.mmsi <= 999999999u);
  check(s.ais_class == 'A' || s.ais_class == 'B');
  check(s.length >= 0.0 && s.length <= 500.0);
  check(s.beam >= 0.0 && s.beam <= 80.0);
  check(finite(s.position));
  check(s.course >= 0.0 && s.course < 2.0 * M_PI);
  check(s.speed >= 0.0 && s.speed <= 60.0 * 1852.0 / 3600.0 + 1e-9);
  check(!s.goal || finite(*s.goal));
  for (const auto& w : s.waypoints)
    check(finite(w));
  check(own || s.behaviour != asv::Behaviour::Waypoints || !s.waypoints.empty());
  check(own || s.behaviour == asv::Behaviour::Waypoints || s.waypoints.empty());
  check(s.planner.empty() || asv::validPlannerName(s.planner));
}

void checkScenario(const asv::Scenario& s) {
  check(s.format == 1);
  check(s.duration > 0.0 && s.duration <= 7 * 86400.0);
  check(std::isfinite(s.min_separation) && s.min_separation > 0.0);
  check(!s.has_origin || asv::validLatLon(s.origin.lat_deg, s.origin.lon_deg));
  (void)s.frame();  // throws (uncaught: a finding) if the origin were invalid
  checkShip(s.own, true);
  std::set<std::string> names{s.own.name};
  std::vector<const asv::ScenarioShip*> all{&s.own};
  for (const auto& t : s.targets) {
    checkShip(t, false);
    check(names.insert(t.name).second);
    all.push_back(&t);
  }
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const double need = std::max(10.0, 0.5 * (all[i]->length + all[j]->length));
      check((all[i]->position - all[j]->position).norm() >= need);
    }
  for (const auto& o : s.obstacles) {
    check(o.polygon.size() >= 3);
    for (const auto& v : o.polygon)
      check(finite(v));
  }
  for (const auto* p : s.planningShips())
    check(!p->planner.empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  asv::Scenario s;
  try {
    s = asv::parseScenario(text, "fuzz.yaml");
  } catch (const asv::ScenarioError& e) {
    check(e.what() && *e.what());
    return 0;
  }
  // Anything else thrown is not caught here: std::terminate, which libFuzzer reports as a crash.
  checkScenario(s);
  return 0;
}
