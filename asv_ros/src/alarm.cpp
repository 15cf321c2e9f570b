#include "asv_ros/alarm.h"

#include <asv_msgs/Alarm.h>

namespace asv_ros {

AlarmReporter::AlarmReporter(ros::NodeHandle nh) : pub_(nh.advertise<asv_msgs::Alarm>("alarms", 1, true)) {
  publish();
}

void AlarmReporter::update(const std::vector<asv::StaleInput>& failed, const std::string& action) {
  std::vector<std::string> inputs;
  inputs.reserve(failed.size());
  for (const asv::StaleInput& f : failed)
    inputs.push_back(f.name);
  const bool changed = inputs != inputs_ || (!inputs.empty() && action != action_);
  causes_.clear();
  for (const asv::StaleInput& f : failed)
    causes_.push_back(f.text);
  if (!changed)
    return;
  const bool was_active = active();
  inputs_ = std::move(inputs);
  action_ = inputs_.empty() ? std::string() : action;
  if (active()) {
    ++raised_;
    ROS_ERROR("%s: ALARM: %s%s%s", ros::this_node::getName().c_str(), causes().c_str(),
              action_.empty() ? "" : "; ", action_.c_str());
  } else if (was_active) {
    ROS_INFO("%s: alarm cleared: every input is back", ros::this_node::getName().c_str());
  }
  publish();
}

std::string AlarmReporter::causes() const {
  std::string s;
  for (const std::string& c : causes_)
    s += (s.empty() ? "" : "; ") + c;
  return s;
}

void AlarmReporter::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const {
  stat.add("alarm", active() ? causes() : std::string("none"));
  stat.add("alarms raised", raised_);
  if (active())
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                 "ALARM: " + causes() + (action_.empty() ? "" : "; " + action_));
}

void AlarmReporter::publish() {
  asv_msgs::Alarm a;
  a.header.stamp = ros::Time::now();
  a.source = ros::this_node::getName();
  a.level = active() ? asv_msgs::Alarm::ERROR : asv_msgs::Alarm::OK;
  a.inputs = inputs_;
  a.causes = causes_;
  a.action = action_;
  pub_.publish(a);
}

double rosNow() {
  return ros::Time::now().toSec();
}

double wallNow() {
  return ros::WallTime::now().toSec();
}

}  // namespace asv_ros
