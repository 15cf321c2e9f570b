#include <asv_core/aco_planner.h>
#include <asv_core/dssa.h>
#include <asv_core/ga_planner.h>
#include <asv_core/mopso_planner.h>
#include <pluginlib/class_list_macros.hpp>

#include "asv_planning/algorithm_plugin.h"

namespace asv_planning {

void AlgorithmPlugin::initialize(const std::string& name, const asv::ParamMap& config) {
  asv::ParamMap merged = defaults_;
  for (const auto& kv : config.values())
    merged.set(kv.first, kv.second);
  algorithm_->configure(merged);
  name_ = name.empty() ? algorithm_->name() : name;
  initialized_ = true;
}

asv::Plan AlgorithmPlugin::makePlan(const asv::PlanningProblem& problem) {
  if (!initialized_)
    throw std::logic_error("planner plugin used before initialize()");
  return algorithm_->plan(problem);
}

AcoPlugin::AcoPlugin() : AlgorithmPlugin(std::make_unique<asv::AcoPlanner>()) {}
namespace {
// DSSA's paper runs in its own units (800 x 800 area, TimeWindow 20, detection range 500). At sea:
// a 10-minute prediction window, intentions exchanged within 6 nm, "collide" below 0.5 nm, a search
// step of 10 s, speed changes of up to 4 m/s (about 8 kn, the paper's range) in 1 m/s steps.
asv::ParamMap dssaSeaDefaults() {
  asv::ParamMap p;
  p.set("time_window", 600.0);
  p.set("detection_range", 11112.0);
  p.set("collision_distance", 926.0);
  p.set("time_step", 10.0);
  p.set("speed_change_max", 4.0);
  p.set("speed_change_step", 1.0);
  return p;
}
}  // namespace

DssaPlugin::DssaPlugin() : AlgorithmPlugin(std::make_unique<asv::DssaPlanner>("dssa"), dssaSeaDefaults()) {}
DssaPlusPlugin::DssaPlusPlugin()
    : AlgorithmPlugin(std::make_unique<asv::DssaPlanner>("dssa_plus"), dssaSeaDefaults()) {}
MopsoPlugin::MopsoPlugin() : AlgorithmPlugin(std::make_unique<asv::MopsoPlanner>()) {}
GaPlugin::GaPlugin() : AlgorithmPlugin(std::make_unique<asv::GaPlanner>()) {}

}  // namespace asv_planning

PLUGINLIB_EXPORT_CLASS(asv_planning::AcoPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::DssaPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::DssaPlusPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::MopsoPlugin, asv_planning::PlannerPlugin)
PLUGINLIB_EXPORT_CLASS(asv_planning::GaPlugin, asv_planning::PlannerPlugin)
