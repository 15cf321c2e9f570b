// Writes a scenario as a format-1 YAML file (asv_bringup/scenarios/README.md), the inverse of
// parseScenario for what generated scenarios use: header, origin, safety, charts, ships with local
// positions, goals, waypoints and recorded tracks, static obstacles. Numbers are rounded for reading
// (positions 0.1 m, courses 0.1 deg, speeds 0.01 kn, lengths 0.1 m, latitude/longitude 1e-7 deg), so a
// program that needs the file's exact values parses the text it wrote.
#pragma once

#include <string>

#include "asv_core/world/scenario.h"

namespace asv {

// Throws std::invalid_argument for what the writer does not cover (sensor faults, planner parameters)
// rather than leave it out silently. Static obstacles are written as they are: a scenario whose charts
// were loaded would carry its land twice, so write one that was parsed, not loaded.
std::string scenarioToYaml(const Scenario& s);

}  // namespace asv
