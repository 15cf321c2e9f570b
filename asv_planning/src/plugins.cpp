// The five planners of asv_core as pluginlib classes of the planner interface, asv::PlannerAlgorithm
// (planner_plugins.xml names them asv_planning/aco, ...): nothing to adapt, the core classes are the
// plugins.
#include <asv_core/planning/aco/aco_planner.h>
#include <asv_core/planning/dssa/dssa.h>
#include <asv_core/planning/ga/ga_planner.h>
#include <asv_core/planning/mopso/mopso_planner.h>
#include <pluginlib/class_list_macros.hpp>

PLUGINLIB_EXPORT_CLASS(asv::AcoPlanner, asv::PlannerAlgorithm)
PLUGINLIB_EXPORT_CLASS(asv::DssaPlanner, asv::PlannerAlgorithm)
PLUGINLIB_EXPORT_CLASS(asv::DssaPlusPlanner, asv::PlannerAlgorithm)
PLUGINLIB_EXPORT_CLASS(asv::MopsoPlanner, asv::PlannerAlgorithm)
PLUGINLIB_EXPORT_CLASS(asv::GaPlanner, asv::PlannerAlgorithm)
