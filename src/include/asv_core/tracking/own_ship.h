// The own ship's state from her own sensors (own_ship_node's logic, free of ROS): GNSS positions (GGA,
// GNS, RMC), course and speed over ground (RMC, VTG), true heading (HDT, THS, HDG with variation), rate
// of turn (ROT) and, as a fallback, her own AIS transponder's reports (AIVDO, or AIVDM from own_mmsi).
//
// Rules:
//  - position: the latest GNSS fix, dead-reckoned to the time asked at its course and speed; her AIS
//    report (if younger than ais_timeout) only while no GNSS fix came for watch/input_timeout. Its
//    1-sigma is HDOP (1.5 when the sentence has none) times the fix type's range error: our choice, from
//    typical receiver figures
//    (GNSS 4 m, DGNSS/SBAS 1 m, PPS 2 m, RTK fixed 0.02 m, RTK float 0.3 m, dead reckoning 50 m, manual or
//    simulator 10 m; an AIS position 10 m with the accuracy flag, 30 m without, as the AIS nodes say);
//  - a fix that would mean a move faster than max_speed since the last is a jump and is rejected
//    (counted); jump_accept fixes in a row that agree with each other are taken as the new position
//    (a receiver that was wrong before, not a glitch now);
//  - heading: a heading sensor's (HDT, THS, HDG); without one for watch/input_timeout, the course over
//    ground stands in while the speed is at least min_speed_for_cog (flagged: heading_from_cog), else
//    the AIS report's heading; none at all: the state has no heading and is not published;
//  - an invalid sentence (no fix, status V) is rejected and counted, never taken as a value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "asv_core/codec/gnss.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/common/input_watch.h"
#include "asv_core/common/units.h"
#include "asv_core/tracking/ingestion_config.h"

namespace asv {

// own_ship_node's keys (asv_risk/config/own_ship_node.yaml documents each), with the ingestion nodes'
// shared ones (origin, frame_id, publish_rate, silence_warning, heartbeat_period, max_sentence_length).
struct OwnShipConfig : IngestionConfig {
  std::string ship = "own";    // <ship>/base_link is the child frame
  std::uint32_t own_mmsi = 0;  // her AIS transponder (0: AIVDO only)
  // [s] her AIS position stands in this long without a GNSS fix (class A under way reports every 2-10 s,
  // class B every 30 s: three missed class A reports, our choice)
  double ais_timeout = 30.0;
  double max_speed = 25.0;                    // [m/s] faster implied moves are jumps (about 50 kn)
  int jump_accept = 3;                        // consistent jumps in a row accepted as the new position
  double min_speed_for_cog = 0.5;             // [m/s] slower, the course over ground is no heading
  std::optional<double> variation;            // [rad] east positive (variation_deg), for HDG without its own
  double heading_sigma = degToRad(1.0);       // [rad] heading sensor 1-sigma
  double cog_heading_sigma = degToRad(10.0);  // [rad] course over ground standing in for heading
  InputWatchConfig watch{2.0, 10.0, 0.5};     // watch/*: fix and heading stale after 2 s: alarm
  // The node also reads a receiver's ROS topics (sensor_msgs/NavSatFix on fix, ENU velocity on vel,
  // orientation on heading), as a GNSS driver such as nmea_navsat_driver publishes them.
  bool navsat = false;
  // The heading topic's yaw: false, an ENU yaw (REP 103: counter-clockwise from east); true, the compass
  // bearing itself (clockwise from north), as nmea_navsat_driver writes HDT into its quaternion.
  bool navsat_heading_is_bearing = false;
  // REP 105: "" (default), tf frame_id -> <ship>/base_link; a name (odom), tf frame_id -> odom_frame ->
  // <ship>/base_link, the odom pose continuous and the fixes' corrections in frame_id -> odom_frame
  // (odom_frame.h). The odometry topic stays in frame_id either way.
  std::string odom_frame;

  void validate() const;
  static OwnShipConfig fromParams(const ParamMap& params);
};

struct OwnShipState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] map (ENU)
  double position_sigma = 0.0;                         // [m] 1-sigma per axis
  double course = 0.0, speed = 0.0;                    // over ground [rad, m/s]
  double heading = 0.0;                                // [rad] true
  double heading_sigma = 0.0;                          // [rad]
  double yaw_rate = 0.0;                               // [rad/s] positive to starboard (0 without ROT)
  bool heading_from_cog = false;
  std::string position_source;  // "GGA", "GNS", "RMC", "AIS"
  gnss::Quality quality = gnss::Quality::kNone;
  double fix_time = 0.0;  // [s] of the position used
};

class OwnShipEstimator {
public:
  OwnShipEstimator(const OwnShipConfig& config, const LocalFrame& frame);

  enum class Use { kUsed, kNotNavigation, kRejected };
  // A framed sentence received at `t` [s, node clock] and `wall` [s]; kRejected fills `why`.
  Use feed(const nmea::Sentence& s, double t, double wall, std::string& why);
  // A position from a receiver that is not read as NMEA (a NavSatFix), named `source`; fix.sigma, when
  // set, replaces the quality's error. An invalid position is kRejected.
  Use position(const gnss::Fix& fix, const char* source, double t, double wall, std::string& why);
  // Course [rad] and speed [m/s] over ground, as RMC's or VTG's.
  void motion(const gnss::Motion& m, double t);
  // True heading [rad] from a heading sensor, as HDT's.
  void heading(double heading, double t, double wall);
  // Her own AIS position report (already decoded).
  void aisReport(double lat_deg, double lon_deg, bool accurate, std::optional<double> course,
                 std::optional<double> speed, std::optional<double> heading, double t);

  // The state at `t` (position dead-reckoned from the fix); empty without a position, a heading or
  // velocity.
  std::optional<OwnShipState> state(double t) const;
  // Inputs gone stale ("fix", "heading"), for the alarm.
  std::vector<StaleInput> stale(double t, double wall);

  uint64_t jumps() const { return jumps_; }
  uint64_t rejected() const { return rejected_; }

private:
  Use takeFix(const gnss::Fix& fix, const char* source, double t, double wall, std::string& why);
  double sigmaOf(const gnss::Fix& fix) const;

  OwnShipConfig cfg_;
  LocalFrame frame_;
  InputWatch watch_;
  std::optional<OwnShipState> fix_;       // last GNSS position (+ its source, quality)
  std::optional<OwnShipState> ais_;       // last own AIS report
  std::optional<double> course_, speed_;  // last GNSS course/speed over ground
  std::optional<double> heading_, rate_;  // last heading sensor, ROT
  double heading_time_ = -1e300, motion_time_ = -1e300, rate_time_ = -1e300;
  std::optional<double> rmc_variation_;
  Eigen::Vector2d jump_candidate_ = Eigen::Vector2d::Zero();
  double jump_candidate_time_ = 0.0;
  int jumps_in_row_ = 0;
  uint64_t jumps_ = 0, rejected_ = 0;
};

}  // namespace asv
