#include "asv_core/sim/run_summary.h"

#include <algorithm>
#include <cmath>

#include "asv_core/risk/cpa.h"

namespace asv {

namespace {

void include(SceneBox& b, const Eigen::Vector2d& p) {
  b.min = b.min.cwiseMin(p);
  b.max = b.max.cwiseMax(p);
}

}  // namespace

SceneBox sceneBox(const Scenario& sc, double margin, double after_cpa) {
  SceneBox b{sc.own.position, sc.own.position};
  double horizon = sc.duration;
  Eigen::Vector2d own_velocity = courseSpeedToVelocity(sc.own.course, sc.own.speed);
  const Eigen::Vector2d to_goal =
      sc.own.goal ? Eigen::Vector2d(*sc.own.goal - sc.own.position) : Eigen::Vector2d::Zero();
  if (sc.own.goal && sc.own.speed > 0.0 && to_goal.norm() > 0.0) {
    own_velocity = to_goal.normalized() * sc.own.speed;
    horizon = std::min(horizon, to_goal.norm() / sc.own.speed);
  }
  include(b, sc.own.position + own_velocity * horizon);
  if (sc.own.goal && to_goal.norm() > 0.0) {
    const Eigen::Vector2d band = 0.4 * Eigen::Vector2d(-to_goal.y(), to_goal.x());
    for (const Eigen::Vector2d& p : {sc.own.position, *sc.own.goal})
      for (double side : {-1.0, 1.0})
        include(b, p + side * band);
  }
  for (const ScenarioShip& t : sc.targets) {
    const Eigen::Vector2d v = courseSpeedToVelocity(t.course, t.speed);
    const double tcpa =
        std::clamp(computeCpa(sc.own.position, own_velocity, t.position, v).tcpa, 0.0, horizon);
    include(b, t.position);
    include(b, t.position + v * std::min(horizon, tcpa + after_cpa));
  }
  const Eigen::Vector2d widen = (b.max - b.min) * margin;
  b.min -= widen;
  b.max += widen;
  // At least 1 nm either side of its centre: a ship lying still with nothing round her is still a view.
  const Eigen::Vector2d centre = (b.min + b.max) / 2.0;
  const Eigen::Vector2d half =
      ((b.max - b.min) / 2.0).cwiseMax(Eigen::Vector2d::Constant(kMetresPerNauticalMile));
  b.min = centre - half;
  b.max = centre + half;
  return b;
}

void RunSummary::update(double t, const Eigen::Vector2d& own, double own_course,
                        const std::map<std::string, Eigen::Vector2d>& targets) {
  for (const auto& [name, p] : targets) {
    const double d = (p - own).norm();
    auto it = closest_.find(name);
    if (it == closest_.end() || d < it->second.distance)
      closest_[name] = {d, t, own, p};
  }
  if (!started_) {
    started_ = true;
    held_ = own_course;
  } else if (!turning_ && std::abs(wrapPi(own_course - held_)) >= min_change_) {
    turning_ = true;
    current_ = {t, own, held_, own_course};
  } else if (turning_ && t > last_t_ &&
             std::abs(wrapPi(own_course - last_course_)) < steady_rate_ * (t - last_t_)) {
    turning_ = false;
    current_.course_to = own_course;
    held_ = own_course;
    if (std::abs(wrapPi(current_.course_to - current_.course_from)) >= min_change_)
      manoeuvres_.push_back(current_);
  }
  last_course_ = own_course;
  last_t_ = t;
}

}  // namespace asv
