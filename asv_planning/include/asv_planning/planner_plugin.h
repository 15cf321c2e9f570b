// The planner plugin interface (nav_core's shape): pure virtual, protected constructor, two-step
// initialisation. Configuration is a plain key/value tree (asv::ParamMap) so that the same plugin
// loads through pluginlib in planner_node (from rosparam) and in asv_batch (from YAML, no master).
#pragma once

#include <string>
#include <vector>

#include <asv_core/common/param_map.h>
#include <asv_core/planning/planning.h>

namespace asv_planning {

class PlannerPlugin {
public:
  virtual ~PlannerPlugin() = default;
  // Second step of the construction: `name` is the plugin's short name (aco, ga, ...), `config` its
  // parameters (keys documented in config/<name>.yaml). Throws std::invalid_argument on a bad or
  // unknown key.
  virtual void initialize(const std::string& name, const asv::ParamMap& config) = 0;
  // Plans for the problem within problem.time_budget; never throws on a feasible problem.
  virtual asv::Plan makePlan(const asv::PlanningProblem& problem) = 0;
  virtual std::string name() const = 0;
  // The parameters in force since initialize(): the plugin's defaults with the given keys over them.
  // What a caller needs to build the same algorithm elsewhere (the distributed DSSA agent does).
  virtual asv::ParamMap parameters() const = 0;
  // The area round each of the problem's targets that this planner keeps the own ship out of (shown in
  // rviz). Not pure: a plugin without a domain of its own shows the separation rule every plan keeps.
  virtual std::vector<asv::TargetDomain> domains(const asv::PlanningProblem& problem) const {
    return asv::separationDomains(problem);
  }
  // The published method plans once and sails the plan (PlannerAlgorithm::plansOnce): paper mode's
  // follower then does not replan on rising risk. Not pure: false, the methods replan.
  virtual bool plansOnce() const { return false; }

protected:
  PlannerPlugin() = default;
};

}  // namespace asv_planning
