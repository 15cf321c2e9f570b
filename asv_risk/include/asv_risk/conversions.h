// Message <-> core struct conversions for the risk node, with the input checks that keep bad data
// out of the engine. No ROS node handle here: unit-testable without a master.
#pragma once

#include <optional>
#include <string>

#include <asv_core/codec/gnss.h>
#include <asv_core/risk/risk_assessment.h>
#include <asv_msgs/Target.h>
#include <asv_msgs/TargetArray.h>
#include <asv_msgs/TargetRisk.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/NavSatFix.h>

namespace asv_risk {

// Why an input was rejected; kCount is the number of reasons (for counters).
enum class Reject { None = 0, NonFinite, Impossible, EmptyId, Duplicate, Stale, Future, Frame, kCount };
const char* toString(Reject r);

// Largest speed over ground taken as real [m/s]: 102.2 kn is the largest AIS can report.
constexpr double kMaxSpeed = 102.2 * asv::kMpsPerKnot;

// Checks and converts a target. Position is taken as already in the working frame.
Reject targetToShipState(const asv_msgs::Target& msg, asv::ShipState& out);

// Converts an odometry message (pose in the working frame, twist in child_frame_id as REP 105 says)
// into the own ship's state over ground.
Reject odometryToShipState(const nav_msgs::Odometry& msg, const std::string& name, asv::ShipState& out);

// The ingestion nodes' sign of life: an empty array stamped now when nothing went out since `last` for
// `period` (or the clock went back); `last` then becomes now. None while the clock is not running.
std::optional<asv_msgs::TargetArray> heartbeatArray(const ros::Time& now, ros::Time& last, double period,
                                                    const std::string& frame_id);

// A receiver's NavSatFix as a fix: its status as the fix quality (FIX: GNSS, SBAS_FIX and GBAS_FIX:
// differential), the horizontal 1-sigma from the covariance (the larger of its east and north
// variances) unless its type is unknown. False, with `why`, for NO_FIX or a position that is no number.
bool navSatToFix(const sensor_msgs::NavSatFix& msg, asv::gnss::Fix& fix, std::string& why);

// A velocity over ground in ENU (x east, y north, m/s, as a GNSS driver's `vel`) as course and speed.
// False for a value that is no number.
bool enuTwistToMotion(const geometry_msgs::TwistStamped& msg, asv::gnss::Motion& motion);

// An orientation as a true heading [rad]: its yaw taken as ENU (REP 103), or with `yaw_is_bearing` as
// the compass bearing itself (nmea_navsat_driver's heading). False for a quaternion that is no rotation.
bool orientationToHeading(const geometry_msgs::QuaternionStamped& msg, bool yaw_is_bearing, double& heading);

// Fills a TargetRisk message from the core result.
asv_msgs::TargetRisk toMsg(const asv::TargetRisk& r, uint32_t mmsi);

}  // namespace asv_risk
