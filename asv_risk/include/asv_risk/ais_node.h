// ais_node: AIVDM sentences in (UDP, TCP, serial, file or the nmea_in topic), decoded AIS targets out.
//
// Subscribes: nmea_in (asv_msgs/NmeaSentence) when input/type is topic
// Publishes:  nmea (asv_msgs/NmeaSentence, every line read from a device), ais/targets
//             (asv_msgs/TargetArray in the local ENU frame of origin_lat_deg/origin_lon_deg: each array
//             holds the ships reported since the previous one, static and voyage data merged per MMSI;
//             an empty one every heartbeat_period when none was), /diagnostics; and the messages that
//             are not ship targets (aids to navigation, SAR aircraft, safety texts, weather):
//             see ais_auxiliary.h
// Parameters: see config/ais_node.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include <asv_core/codec/ais.h>
#include <asv_core/common/clock_jump.h>
#include <asv_core/common/geodesy.h>
#include <asv_core/tracking/ais_targets.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include "asv_risk/ais_auxiliary.h"
#include "asv_risk/nmea_input.h"
#include "asv_risk/params.h"

namespace asv_risk {

// ais_node's parameters (config/ais_node.yaml): asv::AisNodeConfig and the input (frame "ais").
using AisNodeParams = IngestionNodeParams<asv::AisNodeConfig>;

AisNodeParams loadAisParams(const ros::NodeHandle& pnh);

// Why a decoded message did not become a target; kCount is the number of reasons.
enum class AisReject { kNone = 0, kNoPosition, kBadMmsi, kOutOfRange, kCount };
const char* toString(AisReject r);

class AisNode {
public:
  AisNode(ros::NodeHandle nh, ros::NodeHandle pnh);

  // One line of NMEA (as read from the input); public for tests.
  void handleLine(const std::string& line, const ros::Time& stamp);
  std::size_t targetCount() const { return table_.size(); }

private:
  void handleMessage(const asv::ais::Message& m, const ros::Time& stamp);
  void reject(AisReject why, std::uint32_t mmsi);
  void mergeStatic(asv_msgs::Target& t) const;
  void publish();
  // An empty array when nothing was published for heartbeat_period (the tracker's sign of life).
  void heartbeat();
  // Forgets every ship and pending fragment when the clock has gone backwards (a looping bag).
  void checkClock();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  AisNodeParams params_;
  asv_ros::MapOrigin map_origin_;
  asv::LocalFrame frame_;
  asv::nmea::LineFramer framer_;
  asv::ais::Decoder decoder_;
  asv::ais::Message message_;
  asv::ais::StaticStore store_;
  asv::AisTargetTable table_;
  AisAuxiliary aux_;
  ros::Publisher targets_pub_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kIngestion};  // before input_, which subscribes through it
  diagnostic_updater::Updater updater_;
  asv::ClockJumpDetector clock_;
  std::unique_ptr<NmeaInput> input_;  // last: its thread starts once everything else exists

  ros::Time last_publish_;
  std::uint64_t rejected_[static_cast<std::size_t>(AisReject::kCount)] = {};
  std::uint64_t reports_ = 0, own_ship_ = 0, not_ships_ = 0, other_sentences_ = 0;
  std::uint64_t published_ = 0;
  ros::WallTime last_sentence_;
  // For rates and "since the last report" in diagnostics.
  ros::WallTime diag_time_;
  std::uint64_t diag_sentences_ = 0, diag_rejected_ = 0, diag_drops_ = 0;
};

}  // namespace asv_risk
