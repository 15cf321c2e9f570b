// REP 105's odom frame for a ship whose position comes from GNSS fixes.
//
// REP 105 asks that a robot's pose in `odom` move continuously, without the discrete jumps of a global
// fix, and that `map -> odom` carry those jumps. Here the pose in odom is the ship's velocity over ground
// integrated in time (her own motion); `map -> odom` is what the map estimate adds to it. So
// map -> odom -> base_link is the map estimate at every update, while odom -> base_link never jumps when
// a new fix corrects the position. Heading is absolute (a compass), so odom is not rotated from map: the
// transform is a translation.
#pragma once

#include <Eigen/Core>

namespace asv {

class OdomFrame {
public:
  // The ship's map estimate at time t [s] and her velocity over ground [m/s] (east, north). The first
  // update, and one whose time goes back (a clock reset), starts odom at the map position (map -> odom
  // zero). Between updates the pose in odom advances by the previous velocity times the interval.
  void update(double t, const Eigen::Vector2d& map_position, const Eigen::Vector2d& velocity);

  bool started() const { return started_; }
  const Eigen::Vector2d& inOdom() const { return odom_; }     // [m] base_link's position in odom
  Eigen::Vector2d mapToOdom() const { return map_ - odom_; }  // [m] odom's origin in map

private:
  bool started_ = false;
  double t_ = 0.0;
  Eigen::Vector2d odom_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d map_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity_ = Eigen::Vector2d::Zero();
};

}  // namespace asv
