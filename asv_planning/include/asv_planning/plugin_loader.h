// Loads planner plugins by short name (aco, dssa, dssa_plus, mopso, ga) through pluginlib, MoveIt
// style: a failed load says which plugins exist. Needs no ROS master, only the package path (source
// devel/setup.bash), so planner_node and asv_batch share it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pluginlib/class_loader.hpp>

#include "asv_planning/planner_plugin.h"

namespace asv_planning {

class PluginLoader {
public:
  PluginLoader();
  // Short name or full pluginlib name ("asv_planning/aco"). Throws std::runtime_error listing the
  // declared plugins when the name is unknown or the library fails to load, and std::invalid_argument
  // when the configuration is bad.
  // The loader must outlive the plugins it made (it unloads the library with the last one).
  pluginlib::UniquePtr<PlannerPlugin> load(const std::string& name, const asv::ParamMap& config);
  std::vector<std::string> declared() const;
  static std::string fullName(const std::string& name);

private:
  pluginlib::ClassLoader<PlannerPlugin> loader_;
};

}  // namespace asv_planning
