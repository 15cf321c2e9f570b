#include "asv_core/tracking/odom_frame.h"

namespace asv {

void OdomFrame::update(double t, const Eigen::Vector2d& map_position, const Eigen::Vector2d& velocity) {
  if (!started_ || t < t_)
    odom_ = map_position;
  else
    odom_ += velocity_ * (t - t_);
  started_ = true;
  t_ = t;
  map_ = map_position;
  velocity_ = velocity;
}

}  // namespace asv
