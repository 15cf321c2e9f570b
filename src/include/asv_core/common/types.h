// Plain state types shared by the engine. SI units, ENU positions in the `map` frame (x east,
// y north), nautical course (rad, clockwise from true north).
#pragma once

#include <string>

#include <Eigen/Core>

#include "asv_core/common/units.h"

namespace asv {

// Kinematic state of one ship as seen by the risk assessment: where it is and how it moves over ground.
struct ShipState {
  std::string id;                                      // track id or ship name
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
  double course = 0.0;                                 // [rad] course over ground, nautical
  double speed = 0.0;                                  // [m/s] speed over ground
  double heading = 0.0;                                // [rad] nautical; equal to course when unknown
  double length = 0.0;                                 // [m] length overall, 0 when unknown

  Eigen::Vector2d velocity() const { return courseSpeedToVelocity(course, speed); }
  bool finite() const { return allFinite({position.x(), position.y(), course, speed, heading, length}); }
};

}  // namespace asv
