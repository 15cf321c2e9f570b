// What an NMEA 0183 autopilot reads: the stack's course set-point as a route leg, and the sentences
// APB (autopilot sentence B), RMB (recommended minimum navigation information), XTE (cross-track error)
// and HSC (heading steering command), as NMEA 0183 version 4.11 lays them out.
//
// A set-point is a course, not a route; an autopilot in track mode steers a leg. The leg is the
// set-point's course through the point where the ship was when that course was first commanded (a new
// leg when the course changes by more than leg_change). Its destination moves along the leg, lookahead
// metres ahead of the ship's foot point, so the leg never ends and the autopilot never reports arrival
// while the stack steers. The cross-track error is the ship's distance from that line; the heading to
// steer is the bearing to the destination, which brings her back onto it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace asv {
namespace autopilot {

struct LegConfig {
  double lookahead = 1852.0;   // [m] destination this far ahead of the ship's foot point on the leg (1 nm)
  double leg_change = 0.0175;  // [rad] a set-point course this far from the leg's starts a new leg (1 deg)
  void validate() const;       // throws std::invalid_argument
};

// What the sentences carry, in SI (metres, m/s, radians, true bearings).
struct Steering {
  bool valid = true;              // false: status V on every sentence ("do not steer by this")
  double cross_track = 0.0;       // [m] > 0: the ship is right of the leg (steer left)
  double bearing_leg = 0.0;       // [rad] origin to destination
  double bearing_to_dest = 0.0;   // [rad] from the ship
  double heading_to_steer = 0.0;  // [rad]
  double range_to_dest = 0.0;     // [m]
  double closing_speed = 0.0;     // [m/s] towards the destination
  double dest_lat_deg = 0.0, dest_lon_deg = 0.0;
  std::string origin_id = "ASV0", dest_id = "ASV1";
};

// The leg of the set-points, kept from one call to the next.
class SetpointLeg {
public:
  explicit SetpointLeg(const LegConfig& config = {});
  // Steering for a set-point course (rad, true) with the ship at `position` (map, m) making
  // `course_over_ground` at `speed` (m/s). dest_lat/lon are left for the caller (it has the map origin).
  Steering update(double setpoint_course, const Eigen::Vector2d& position, double course_over_ground,
                  double speed);
  Eigen::Vector2d destination() const { return destination_; }
  int legs() const { return legs_; }  // legs started so far (the id of the present one)
  void reset() { have_leg_ = false; }

private:
  LegConfig cfg_;
  bool have_leg_ = false;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero(), destination_ = Eigen::Vector2d::Zero();
  double course_ = 0.0;
  int legs_ = 0;
};

// "$<talker>APB,...": cross-track in nautical miles, bearings true, mode A (autonomous) or V when invalid.
std::string encodeApb(const Steering& s, const std::string& talker = "EC");
// "$<talker>RMB,...": range in nautical miles, bearing true, closing velocity in knots.
std::string encodeRmb(const Steering& s, const std::string& talker = "EC");
// "$<talker>XTE,...".
std::string encodeXte(const Steering& s, const std::string& talker = "EC");
// "$<talker>HSC,...": heading true, and magnetic when the variation (rad, east positive) is known.
std::string encodeHsc(double heading_true, std::optional<double> variation, const std::string& talker = "EC");

// "$<talker>WPL,...": a waypoint's position and name (a chart plotter's waypoint list).
std::string encodeWpl(double lat_deg, double lon_deg, const std::string& name,
                      const std::string& talker = "EC");
// "$<talker>RTE,...": a route's waypoint names in order, as many sentences as fit 82 characters each
// (the first field the count, the second each one's number; c: the complete route).
std::vector<std::string> encodeRte(const std::string& route_name, const std::vector<std::string>& waypoints,
                                   const std::string& talker = "EC");

// NMEA position fields: "ddmm.mmmm,N" and "dddmm.mmmm,E".
std::string latitudeField(double lat_deg);
std::string longitudeField(double lon_deg);

}  // namespace autopilot
}  // namespace asv
