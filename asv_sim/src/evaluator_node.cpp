#include "asv_sim/evaluator_node.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <asv_ros/params.h>
#include <filesystem>

namespace asv_sim {

namespace {

asv::SimEvent::Type toCore(uint8_t type) {
  switch (type) {
    case asv_msgs::SimEvent::COLLISION:
      return asv::SimEvent::Collision;
    case asv_msgs::SimEvent::NEAR_MISS:
      return asv::SimEvent::NearMiss;
    case asv_msgs::SimEvent::GROUNDING:
      return asv::SimEvent::Grounding;
    default:
      return asv::SimEvent::Arrival;
  }
}

}  // namespace

asv::EvaluatorNodeConfig loadEvaluatorParams(const ros::NodeHandle& pnh) {
  // evaluation/ is EvaluationConfig's: its fromParams rejects the subtree's unknown keys.
  return asv_ros::loadConfig<asv::EvaluatorNodeConfig>(pnh, "asv_sim/config/evaluator_node.yaml",
                                                       {"evaluation/"});
}

EvaluatorNode::EvaluatorNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh), pnh_(pnh), params_(loadEvaluatorParams(pnh)) {
  if (!params_.scenario.empty())
    scenario_ = std::make_unique<asv::Scenario>(asv::loadScenario(params_.scenario, params_.charts));
  // Lockstep: samples, then plans and set-points, then events; only an event wakes the node (the END
  // event writes the result), and everything before it is delivered first, in order.
  ships_sub_ = lockstep_.subscribe("sim/ships", 20, &EvaluatorNode::shipsCallback, this, false);
  plan_sub_ = lockstep_.subscribe(params_.own_ship + "/plan", 20, &EvaluatorNode::planCallback, this, false);
  cmd_sub_ = lockstep_.subscribe(params_.own_ship + "/cmd", 50, &EvaluatorNode::cmdCallback, this, false);
  events_sub_ = lockstep_.subscribe("sim/events", 100, &EvaluatorNode::eventCallback, this);
  lockstep_.start();
  wall_start_ = ros::WallTime::now();
  ROS_INFO("evaluator_node: own ship '%s', result %s", params_.own_ship.c_str(),
           params_.result.empty() ? "(not written)" : params_.result.c_str());
}

void EvaluatorNode::start(const asv_msgs::TargetArray& first) {
  asv::RunInfo info;
  if (scenario_) {
    info = asv::RunInfo::fromScenario(*scenario_, "", static_cast<uint64_t>(params_.seed));
    if (info.ships.front().name != params_.own_ship)
      throw std::invalid_argument("own_ship '" + params_.own_ship + "' is not the scenario's own ship '" +
                                  info.ships.front().name + "'");
  } else {
    info.scenario = "unknown";
    info.seed = static_cast<uint64_t>(params_.seed);
    info.ships.push_back({params_.own_ship, std::nullopt, ""});
    for (const auto& t : first.targets)
      if (t.id != params_.own_ship)
        info.ships.push_back({t.id, std::nullopt, ""});
  }
  std::string planner = params_.planner;
  if (planner.empty())
    planner = scenario_ && !scenario_->own.planner.empty() ? scenario_->own.planner : "none";
  info.planner = planner;
  info.ships.front().planner = planner;
  recorder_ = std::make_unique<asv::RunRecorder>(params_.evaluation, info);
  for (const auto& e : pending_)
    recorder_->addEvent(e);
  pending_.clear();
}

void EvaluatorNode::shipsCallback(const asv_msgs::TargetArray::ConstPtr& msg) {
  if (done_)
    return;
  if (clock_.jumpedBack(msg->header.stamp.toSec()) && recorder_) {
    ROS_WARN("evaluator_node: the run's time went back %.1f s (a looping bag?): recording starts again",
             clock_.lastJump());
    recorder_.reset();
    arrived_.clear();
  }
  try {
    if (!recorder_)
      start(*msg);
  } catch (const std::exception& e) {
    ROS_FATAL("evaluator_node: %s", e.what());
    ros::shutdown();
    return;
  }
  std::vector<asv::ShipSample> ships;
  for (const auto& t : msg->targets) {
    asv::ShipSample s;
    s.name = t.id;
    s.state.id = t.id;
    s.state.position = {t.position.x, t.position.y};
    s.state.course = t.course_over_ground;
    s.state.speed = t.speed_over_ground;
    s.state.heading = t.has_heading ? t.heading : t.course_over_ground;
    s.state.length = t.length;
    s.beam = t.beam;
    s.active = !arrived_.count(t.id);
    ships.push_back(s);
  }
  recorder_->addSample(simTime(msg->header.stamp), ships);
}

void EvaluatorNode::eventCallback(const asv_msgs::SimEvent::ConstPtr& msg) {
  if (done_)
    return;
  if (msg->type == asv_msgs::SimEvent::END) {
    finish();
    return;
  }
  asv::SimEvent e{toCore(msg->type), simTime(msg->header.stamp), msg->ship_a, msg->ship_b, msg->distance};
  if (e.type == asv::SimEvent::Arrival)
    arrived_.insert(e.a);
  if (recorder_)
    recorder_->addEvent(e);
  else
    pending_.push_back(e);
}

void EvaluatorNode::planCallback(const asv_msgs::Plan::ConstPtr& msg) {
  if (recorder_ && !done_) {
    recorder_->addPlanTime(msg->compute_time);
    recorder_->addPassingDistance(msg->passing_distance);
  }
}

void EvaluatorNode::cmdCallback(const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg) {
  if (recorder_ && !done_)
    recorder_->addSetpoint(simTime(msg->header.stamp), params_.own_ship, msg->course);
}

// Writes one output file (its folders created); "" = not asked for. A failure is an error on screen,
// never a crash at the end of a run.
void EvaluatorNode::writeOutput(const std::string& file, const std::string& text, const char* what) {
  if (file.empty())
    return;
  try {
    const std::filesystem::path path(file);
    if (path.has_parent_path())
      std::filesystem::create_directories(path.parent_path());
    std::ofstream f(file);
    f << text;
    if (!f)
      throw std::runtime_error("write failed");
    ROS_INFO("evaluator_node: %s written to %s", what, file.c_str());
  } catch (const std::exception& e) {
    ROS_ERROR("evaluator_node: cannot write %s %s: %s", what, file.c_str(), e.what());
  }
}

void EvaluatorNode::finish() {
  done_ = true;
  if (!recorder_) {
    ROS_ERROR("evaluator_node: the run ended before any sim/ships message: no result");
  } else {
    recorder_->setWallTime((ros::WallTime::now() - wall_start_).toSec());
    const asv::RunResult r = recorder_->finish();
    std::istringstream table(asv::summaryTable(r));
    for (std::string line; std::getline(table, line);)
      ROS_INFO("evaluator_node: %s", line.c_str());
    writeOutput(params_.result, asv::toJson(r, params_.pretty) + "\n", "result");
    writeOutput(params_.geojson, recorder_->geoJson(r), "GeoJSON");
  }
  if (params_.shutdown_at_end)
    ros::shutdown();
}

}  // namespace asv_sim
