// A planner target for tests: a ship at `pos` [m] on `course_deg` at `speed` [m/s], no risk picture.
#pragma once

#include <string>

#include "asv_core/common/units.h"
#include "asv_core/planning/planning.h"

inline asv::PlannerTarget plannerTarget(const std::string& id, const Eigen::Vector2d& pos, double course_deg,
                                        double speed) {
  asv::PlannerTarget t;
  t.state.id = id;
  t.state.position = pos;
  t.state.course = t.state.heading = asv::degToRad(course_deg);
  t.state.speed = speed;
  return t;
}
