// The AIS messages of ais_node that are not ship targets: aids to navigation (message 21), SAR
// aircraft (9), safety-related texts (12, 14) and weather (8, DAC 1 FID 31).
//
// Publishes (in ais_node's namespace):
//   ais/aids_to_navigation (asv_msgs/AidToNavigationArray, latched): every aid known, every
//       aids/publish_period, for display and for the planners (static hazards)
//   ais/sar_aircraft (asv_msgs/TargetArray): SAR aircraft reported since the previous array, at
//       publish_rate; position.z is the altitude [m]. Shown, never given to the tracker: an aircraft
//       is not a collision target.
//   ais/safety_messages (asv_msgs/AisSafetyMessage): each text as received, also logged at WARN
//   ais/weather (asv_msgs/AisWeather): each IMO289 met/hydro report as received
//   ais/markers, ais/sar_markers (visualization_msgs/MarkerArray, when publish_markers): the aids
//       (yellow: a mark, magenta: virtual, red: off position) and the SAR aircraft, for rviz
#pragma once

#include <cstdint>

#include <asv_core/codec/ais.h>
#include <asv_core/common/geodesy.h>
#include <asv_core/tracking/ais_targets.h>
#include <asv_msgs/AidToNavigationArray.h>
#include <asv_msgs/AisSafetyMessage.h>
#include <asv_msgs/AisWeather.h>
#include <asv_msgs/Target.h>
#include <asv_msgs/TargetArray.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include "asv_risk/params.h"

namespace asv_risk {

// The Target message of an AIS target (ship or SAR aircraft; an aircraft's altitude is position.z).
asv_msgs::Target aisTargetMsg(const asv::AisTarget& s);

// Conversions of the auxiliary messages (no node handle: unit-testable).
asv_msgs::AidToNavigation aidMsg(const asv::AidRecord& a, const ros::Time& now);
asv_msgs::AisSafetyMessage safetyMsg(const asv::ais::Message& m, const asv::ais::SafetyText& t);
asv_msgs::AisWeather weatherMsg(std::uint32_t mmsi, const asv::ais::MetHydroReport& r,
                                const asv::LocalFrame& frame);

class AisAuxiliary {
public:
  // The node's jobs call publishSar() and publishAids() (at publish_rate and aids/publish_period).
  AisAuxiliary(ros::NodeHandle nh, const asv::AisNodeConfig& config, const asv::LocalFrame& frame);

  // A decoded message (its payload `p`) received at `stamp`: true when it is one of the kinds above
  // (then handled here), false for the rest.
  bool handle(const asv::ais::Message& m, const asv::ais::Payload& p, const ros::Time& stamp);
  // The SAR aircraft reported since the last call (publish_rate job).
  void publishSar(const ros::Time& now);
  // Every aid, and the markers (aids/publish_period job).
  void publishAids(const ros::Time& now);
  void clear();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const;

private:
  // Counts and logs (throttled) a report that is not used.
  void refuse(const char* what, std::uint32_t mmsi, const char* why);
  void handleWeather(const asv::ais::Message& m, const asv::ais::Payload& p, const ros::Time& stamp);
  void publishMarkers(const ros::Time& now);

  const asv::AisNodeConfig& config_;
  asv::LocalFrame frame_;
  asv::AidTable aids_;
  asv::AisTargetTable sar_;
  ros::Publisher aids_pub_, sar_pub_, safety_pub_, weather_pub_, markers_pub_, sar_markers_pub_;
  std::uint64_t aid_reports_ = 0, sar_reports_ = 0, texts_ = 0, weather_reports_ = 0, refused_ = 0;
};

}  // namespace asv_risk
