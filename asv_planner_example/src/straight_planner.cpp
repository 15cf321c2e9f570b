// A planner of a package other than asv_planning, loaded by pluginlib as any of the five: it derives
// from asv::PlannerAlgorithm, reads its parameters in configure(), plans in plan(), and is exported
// with PLUGINLIB_EXPORT_CLASS and planner_plugins.xml. It steers the course to the next waypoint at
// speed_fraction of the cruise speed and avoids nothing itself: the plan follower's shared rules
// (asv::PlanFollower::acceptPlan) keep every plan clear of other ships and land.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <asv_core/common/units.h>
#include <asv_core/planning/planning.h>
#include <pluginlib/class_list_macros.hpp>

namespace asv_planner_example {

class StraightPlanner : public asv::PlannerAlgorithm {
public:
  // Key speed_fraction: of the cruise speed, in (0, 1]; default 1. Unknown keys are refused, as
  // every planner of the stack refuses them (a typo must not pass for a setting).
  void configure(const asv::ParamMap& params) override {
    const double f = params.getDouble("speed_fraction", 1.0);
    params.rejectUnknown("straight");
    if (!(f > 0.0 && f <= 1.0))
      throw std::invalid_argument("straight: speed_fraction must be in (0, 1], got " + std::to_string(f));
    speed_fraction_ = f;
  }

  asv::Plan plan(const asv::PlanningProblem& problem) override {
    const Eigen::Vector2d aim = asv::nextWayPoint(problem);
    const Eigen::Vector2d leg = aim - problem.own.position;
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = leg.norm() > 0.0 ? asv::courseOf(leg) : problem.own.course;
    plan.speed_setpoint = std::min(speed_fraction_ * asv::keptSpeed(problem), problem.limits.max_speed);
    plan.waypoints.push_back({problem.own.position, 0.0, plan.course_setpoint, plan.speed_setpoint});
    if (plan.speed_setpoint > 0.0)
      plan.waypoints.push_back(
          {aim, leg.norm() / plan.speed_setpoint, plan.course_setpoint, plan.speed_setpoint});
    plan.message = "straight for the next waypoint";
    return plan;
  }

  std::string name() const override { return "straight"; }

private:
  double speed_fraction_ = 1.0;
};

}  // namespace asv_planner_example

PLUGINLIB_EXPORT_CLASS(asv_planner_example::StraightPlanner, asv::PlannerAlgorithm)
