// Loads planners through pluginlib, MoveIt style: any class of base type asv::PlannerAlgorithm that a
// package exports (<asv_planning plugin="..."/> in its package.xml) loads by its pluginlib name, and a
// failed load says which ones exist. Needs no ROS master, only the package path (source
// devel/setup.bash or install/setup.bash), so planner_node and asv_batch share it.
#pragma once

#include <string>
#include <vector>

#include <asv_core/common/param_map.h>
#include <asv_core/planning/planning.h>
#include <pluginlib/class_loader.hpp>

namespace asv_planning {

class PluginLoader {
public:
  PluginLoader();
  // `name`: a pluginlib class name ("asv_planning/aco", "my_pkg/my_planner"), or a short name, which is
  // this package's ("aco" is "asv_planning/aco"). Initialised with `config` (asv::PlannerAlgorithm::
  // initialize). Throws std::runtime_error listing the declared planners when the name is unknown or
  // the library fails to load, and std::invalid_argument when the configuration is bad.
  // The loader must outlive the planners it made (it unloads the library with the last one).
  pluginlib::UniquePtr<asv::PlannerAlgorithm> load(const std::string& name, const asv::ParamMap& config);
  // Every declared planner's pluginlib name.
  std::vector<std::string> declared() const;
  // The name a planner's parameters go under (~<name>/, planner_params.<name>): the short name for
  // this package's, the full pluginlib name for another package's.
  std::vector<std::string> parameterNames() const;
  static std::string fullName(const std::string& name);
  static std::string parameterName(const std::string& name);

private:
  pluginlib::ClassLoader<asv::PlannerAlgorithm> loader_;
};

}  // namespace asv_planning
