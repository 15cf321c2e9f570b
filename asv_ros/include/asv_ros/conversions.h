// The conversions between ROS messages and asv_core's types, one each, with the input checks that
// keep bad data out of the engine (every node uses these; no node handle: unit-testable without a
// master), and the small ROS helpers the nodes share: marker scale, the clock-jump reset.
#pragma once

#include <functional>
#include <string>

#include <asv_core/codec/gnss.h>
#include <asv_core/common/clock_jump.h>
#include <asv_core/planning/planning.h>
#include <asv_core/risk/risk_assessment.h>
#include <asv_msgs/Target.h>
#include <asv_msgs/TargetRisk.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>

namespace asv_ros {

// Why an input was rejected; kCount is the number of reasons (for counters).
enum class Reject { None = 0, NonFinite, Impossible, EmptyId, Duplicate, Stale, Future, Frame, kCount };
const char* toString(Reject r);

// Largest speed over ground taken as real [m/s]: 102.2 kn is the largest AIS can report.
constexpr double kMaxSpeed = 102.2 * asv::kMpsPerKnot;

// Checks and converts a target (asv_msgs/Target: ingestion, the tracker, the simulator's ground truth).
// Position is taken as already in the working frame.
Reject targetToShipState(const asv_msgs::Target& msg, asv::ShipState& out);

// Checks and converts an odometry message (pose in the working frame, twist in child_frame_id as REP 105
// says) into a ship's state over ground: position and heading from the pose, course and speed over
// ground from the twist rotated into the working frame. Every node that takes odometry uses it.
Reject odometryToShipState(const nav_msgs::Odometry& msg, const std::string& name, asv::ShipState& out);

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

// The encounter and role in the message's vocabulary (asv_msgs/TargetRisk: a crossing and its side as the
// role; head-on, give way) and back: a crossing stands on only with ROLE_STAND_ON.
uint8_t encounterToMsg(asv::Encounter e);
uint8_t roleToMsg(asv::OwnRole r);
asv::Encounter encounterFromMsg(uint8_t encounter, uint8_t role);

// Fills a TargetRisk message from the core result.
asv_msgs::TargetRisk toMsg(const asv::TargetRisk& r, uint32_t mmsi);
// The risk fields of a TargetRisk message as the planners see them (risk level, compliance, encounter,
// role, CRI, TCPA, DCPA); the track is the target's (selectPlannerTargets joins the two). False when the
// encounter is a value this node does not know (a newer message): it is then none, and the caller
// says so; the risk level still counts.
bool riskFromMsg(const asv_msgs::TargetRisk& m, asv::PlannerTarget& out);

// The orientation of an ENU yaw [rad] (REP 103: counter-clockwise from east, about z up).
geometry_msgs::Quaternion yawToQuaternion(double yaw);

// rviz marker sizes: `px` screen pixels as metres in the map, at the global parameter /view_scale
// [px/m] (default 0.06, asv_bringup/rviz/asv.rviz's top-down scale; rviz/record.sh sets the scale of
// its fitted view), so that ships and labels stay readable at any zoom the run is shown at.
double pixelsToMetres(double px);

// When ROS time has gone back (a looping bag, a restarted simulator; asv::ClockJumpDetector), a node
// forgets its time-dependent state rather than computing ages and rates across the jump: `reset`
// forgets it and says what it forgot ("12 tracks dropped"), which is logged as a warning; the
// diagnostics are published at once (diagnostic_updater schedules by ROS time and would otherwise
// stay silent until the clock caught up). Returns true when the clock jumped.
bool resetOnClockJump(asv::ClockJumpDetector& clock, diagnostic_updater::Updater& updater,
                      const ros::Time& now, const std::function<std::string()>& reset);

}  // namespace asv_ros
