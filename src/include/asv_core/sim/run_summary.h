// What a run's picture keeps for its last frame (sim_node's summary markers, rviz/record.sh): the part
// of the sea the encounter takes place in, each target's closest approach to the own ship, and the
// own ship's manoeuvres.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "asv_core/common/units.h"
#include "asv_core/world/scenario.h"

namespace asv {

struct SceneBox {
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Zero();  // [m] map
};

// The box round every ship's start, the own ship's goal with a band of 0.4 x her distance to it either
// side of her straight track (a manoeuvre takes her off it, to a side the box cannot know), and each
// target's predicted track (her start course and speed) up to `after_cpa` past her closest approach to
// the own ship sailing straight for her goal at her speed, and no longer than the own ship takes to get
// there (the scenario's duration without a goal); widened by `margin` of its size on each side, and at
// least 1 nm either side of its centre. A target's far future is left out: the picture is about the
// encounter, not where she goes after it.
SceneBox sceneBox(const Scenario& sc, double margin = 0.1, double after_cpa = 600.0);

struct ClosestApproach {
  double distance = 0.0;                                                            // [m]
  double t = 0.0;                                                                   // [s] simulated time
  Eigen::Vector2d own = Eigen::Vector2d::Zero(), target = Eigen::Vector2d::Zero();  // [m] map
};

// A change of the own ship's course over ground as sailed (the evaluator's manoeuvres, eval/evaluation.h,
// are changes of the commanded course; the two differ by the ship's turning and the autopilot).
struct CourseAlteration {
  double t = 0.0;                                      // [s] when her course left the course held
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] where
  double course_from = 0.0, course_to = 0.0;           // [rad] the course held before and after
};

class RunSummary {
public:
  // A manoeuvre: her course over ground leaves the course held by at least min_change, and ends when it
  // turns by less than steady_rate over the interval between two updates.
  explicit RunSummary(double min_change = degToRad(5.0), double steady_rate = degToRad(0.1))
      : min_change_(min_change), steady_rate_(steady_rate) {}

  // One sample of the run: the own ship's position and course over ground, and the targets' positions.
  void update(double t, const Eigen::Vector2d& own, double own_course,
              const std::map<std::string, Eigen::Vector2d>& targets);

  const std::map<std::string, ClosestApproach>& closest() const { return closest_; }
  // The finished manoeuvres; one still turning is not among them.
  const std::vector<CourseAlteration>& manoeuvres() const { return manoeuvres_; }

private:
  double min_change_, steady_rate_;
  std::map<std::string, ClosestApproach> closest_;
  std::vector<CourseAlteration> manoeuvres_;
  bool started_ = false, turning_ = false;
  double held_ = 0.0, last_course_ = 0.0, last_t_ = 0.0;
  CourseAlteration current_;
};

}  // namespace asv
