// The radar side of the target picture: the latest fix of every target the ARPA reports (TTM range and
// bearing from the own ship, or TLL position), as the ARPA ingestion node publishes it to the tracker.
// ROS-free, so that the rules (which own-ship data a fix needs, how sure its position is, what the
// velocity and quality are, who is forgotten) are unit-tested here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include <Eigen/Core>

#include "asv_core/codec/arpa.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/tracking/ais_targets.h"
#include "asv_core/tracking/radar_fix.h"

namespace asv {

struct ArpaTargetConfig {
  double max_range = 200000.0;     // [m] TLL positions farther from the map origin are rejected
  std::size_t max_targets = 1000;  // targets remembered; a new one evicts the least recently heard
  double forget_after = 120.0;     // [s] a target not heard for this long is forgotten
  double odom_timeout = 2.0;       // [s] own position/heading older than this is not used
  RadarSigmas sigmas;              // of a TTM range and bearing
  double tll_sigma = 50.0;         // [m] 1-sigma of a TLL position, either axis
  void validate() const;           // std::invalid_argument naming the first bad field
};

// How far a target's data goes: a TTM with course and speed (or speed 0) gives a velocity, the
// radar's status Q (acquiring) a tentative one; without them the velocity is unknown.
enum class ArpaQuality : std::uint8_t { Tracking, Acquiring, NoVelocity };

struct ArpaTarget {
  int number = 0;  // the radar's target number, 0..65535
  std::string name;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();    // [m] map frame
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  // [m^2] of the position, ENU
  bool has_geodetic = false;
  double lat_deg = 0.0, lon_deg = 0.0;
  bool has_velocity = false;
  double course = 0.0, speed = 0.0;                    // [rad] nautical in [0, 2 pi), [m/s]; 0 when unknown
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s] ENU; 0 when unknown
  bool acquiring = false;                              // the last TTM said status Q
  std::int64_t stamp_ns = 0;                           // receive time of the last fix
  bool updated = false;                                // fixed since the last due()
  ArpaQuality quality() const;
};

// What became of a sentence.
enum class ArpaOutcome : std::uint8_t {
  Target,         // a target was updated
  Lost,           // status L: the target is dropped
  NoNumber,       // target number outside 0..65535
  NoPosition,     // no range and bearing (TTM) or position (TLL)
  NoOwnPosition,  // TTM without a recent own position
  NoOwnHeading,   // TTM relative bearing without a recent own heading
  OutOfRange      // TLL beyond max_range
};

class ArpaTargetTable {
public:
  ArpaTargetTable(const ArpaTargetConfig& cfg, const LocalFrame& frame);

  // The own ship from the navigation sensors (position [m, map], heading [rad] nautical).
  void ownShip(const Eigen::Vector2d& position, double heading, std::int64_t stamp_ns);
  // The own heading from the radar's OSD; used when the navigation heading is stale.
  void osdHeading(double heading, std::int64_t stamp_ns);
  // A parsed TTM / TLL received at stamp_ns.
  ArpaOutcome ttm(const arpa::TrackedTarget& tt, std::int64_t stamp_ns);
  ArpaOutcome tll(const arpa::TargetPosition& tp, std::int64_t stamp_ns);
  // Forgets the targets not heard for forget_after at now_ns, then calls f(target, age [s]) for each
  // target fixed since the last call, by target number.
  template <class F>
  void due(std::int64_t now_ns, F f);

  std::size_t size() const { return targets_.size(); }
  bool hasOwnShip() const { return has_own_; }
  std::uint64_t lost() const { return lost_; }        // dropped on status L
  std::uint64_t evicted() const { return evicted_; }  // forgotten because the table was full
  // Forgets every target and the own ship (the clock went backwards).
  void clear();

private:
  bool fresh(std::int64_t stamp_ns, std::int64_t now_ns) const;
  // NoNumber for a number outside 0..65535; Lost (the target dropped) for status L; else Target.
  ArpaOutcome checkNumber(int number, arpa::TargetStatus status);
  ArpaTarget& target(int number, std::int64_t stamp_ns);
  static void setVelocity(ArpaTarget& t, const arpa::TrackedTarget& tt);

  ArpaTargetConfig cfg_;
  LocalFrame frame_;
  std::map<int, ArpaTarget> targets_;
  bool has_own_ = false, has_osd_heading_ = false;
  Eigen::Vector2d own_position_ = Eigen::Vector2d::Zero();
  double own_heading_ = 0.0, osd_heading_ = 0.0;
  std::int64_t own_stamp_ns_ = 0, osd_stamp_ns_ = 0;
  std::uint64_t lost_ = 0, evicted_ = 0;
};

template <class F>
void ArpaTargetTable::due(std::int64_t now_ns, F f) {
  dueTargets(targets_, now_ns, cfg_.forget_after, f);
}

}  // namespace asv
