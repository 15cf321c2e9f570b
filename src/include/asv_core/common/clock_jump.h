// Detects time going backwards: a bag played with --loop, a simulator restarted, a clock source reset.
// The ROS nodes feed it ros::Time::now() and reset their time-dependent state (tracks, histories, plans,
// recordings) when it fires, rather than computing ages, predictions and rates across the jump.
#pragma once

#include <cmath>
#include <cstdint>

namespace asv {

class ClockJumpDetector {
public:
  // `tolerance` [s]: a step back of up to this much is jitter (stamps of concurrent callbacks), not a
  // jump. Default 1 s.
  explicit ClockJumpDetector(double tolerance = 1.0) : tolerance_(tolerance > 0.0 ? tolerance : 0.0) {}

  // True when `now` [s] lies more than the tolerance before the latest time seen (the latest then
  // becomes `now`). Non-finite times and times of 0 (a ROS clock not yet received) are ignored.
  bool jumpedBack(double now) {
    if (!std::isfinite(now) || now == 0.0)
      return false;
    if (seen_ && now < latest_ - tolerance_) {
      last_jump_ = latest_ - now;
      latest_ = now;
      ++jumps_;
      return true;
    }
    if (!seen_ || now > latest_)
      latest_ = now;
    seen_ = true;
    return false;
  }

  std::uint64_t jumps() const { return jumps_; }
  double lastJump() const { return last_jump_; }  // [s] size of the latest jump back
  double latest() const { return latest_; }

private:
  double tolerance_;
  double latest_ = 0.0;
  double last_jump_ = 0.0;
  bool seen_ = false;
  std::uint64_t jumps_ = 0;
};

}  // namespace asv
