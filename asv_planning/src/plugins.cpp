#include <asv_core/planning/aco/aco_planner.h>
#include <asv_core/planning/dssa/dssa.h>
#include <asv_core/planning/ga/ga_planner.h>
#include <asv_core/planning/mopso/mopso_planner.h>
#include <pluginlib/class_list_macros.hpp>

#include "asv_planning/algorithm_plugin.h"

namespace asv_planning {

void AlgorithmPlugin::initialize(const std::string& name, const asv::ParamMap& config) {
  // The sea-scale defaults belong to sea mode; paper mode runs the paper's own values and units.
  asv::ParamMap merged =
      asv::plannerMode(config, algorithm_->name()) == asv::PlannerMode::Paper ? asv::ParamMap{} : defaults_;
  for (const auto& kv : config.values())
    merged.set(kv.first, kv.second);
  algorithm_->configure(merged);
  parameters_ = merged;
  name_ = name.empty() ? algorithm_->name() : name;
  initialized_ = true;
}

asv::Plan AlgorithmPlugin::makePlan(const asv::PlanningProblem& problem) {
  if (!initialized_)
    throw std::logic_error("planner plugin used before initialize()");
  return algorithm_->plan(problem);
}

AcoPlugin::AcoPlugin() : AlgorithmPlugin(std::make_unique<asv::AcoPlanner>()) {}
// DSSA's paper runs in its own units; the plugins start from the sea-scale defaults of asv_core.
DssaPlugin::DssaPlugin()
    : AlgorithmPlugin(std::make_unique<asv::DssaPlanner>("dssa"), asv::DssaConfig::seaDefaults()) {}
DssaPlusPlugin::DssaPlusPlugin()
    : AlgorithmPlugin(std::make_unique<asv::DssaPlanner>("dssa_plus"), asv::DssaConfig::seaDefaults()) {}
MopsoPlugin::MopsoPlugin() : AlgorithmPlugin(std::make_unique<asv::MopsoPlanner>()) {}
GaPlugin::GaPlugin() : AlgorithmPlugin(std::make_unique<asv::GaPlanner>()) {}

}  // namespace asv_planning

PLUGINLIB_EXPORT_CLASS(asv_planning::AcoPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::DssaPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::DssaPlusPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::MopsoPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::GaPlugin, asv_planning::PlannerPlugin)
