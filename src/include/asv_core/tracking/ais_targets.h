// The AIS side of the target picture: the latest position report of every ship heard, as the AIS
// ingestion node publishes it to the tracker. ROS-free, so that the rules (what is a ship, which
// velocity a report gives, how sure its position is, who is forgotten) are unit-tested here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>

#include <Eigen/Core>

#include "asv_core/codec/ais.h"
#include "asv_core/common/geodesy.h"

namespace asv {

struct AisTargetConfig {
  double max_range = 200000.0;        // [m] positions farther from the map origin are rejected
  std::size_t max_targets = 5000;     // ships remembered; a new one evicts the least recently heard
  double forget_after = 900.0;        // [s] a ship not heard for this long is forgotten
  double position_sigma_high = 10.0;  // [m] 1-sigma of a fix with the accuracy flag set (DGNSS)
  double position_sigma_low = 30.0;   // [m] 1-sigma of a fix without it (GNSS)
  // Keep SAR aircraft (type 9) instead of ships: they are shown, never collision targets, so the
  // node keeps them in a table of their own.
  bool sar_aircraft = false;
  // The own ship's transponder: her AIVDM reports (a shore log replayed with one of its vessels as
  // the own ship) are not a target, as AIVDO never is. 0: none.
  std::uint32_t own_mmsi = 0;
  void validate() const;  // std::invalid_argument naming the first bad field
};

// Where a target's velocity comes from. AIS gives course and speed over ground; without a course the
// true heading stands in (a ship makes good roughly her heading); a ship reporting speed 0 without a
// course is stopped; otherwise the velocity is unknown.
enum class AisVelocity : std::uint8_t { Reported, CourseFromHeading, Unknown };

struct AisTarget {
  std::uint32_t mmsi = 0;
  char ais_class = 'A';          // 'A' (types 1-3 and 27), 'B' (18, 19) or 'S' (SAR aircraft, 9)
  std::uint8_t nav_status = 15;  // ITU-R M.1371 navigational status; 15: not defined (class B)
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] map frame
  double lat_deg = 0.0, lon_deg = 0.0;
  AisVelocity velocity = AisVelocity::Unknown;
  double course = 0.0, speed = 0.0;  // [rad] nautical as reported, [m/s]; 0 when unknown
  bool has_heading = false;
  double heading = 0.0;  // [rad] true heading
  bool has_turn = false;
  double rate_of_turn = 0.0;  // [rad/s] positive clockwise
  double sigma = 0.0;         // [m] 1-sigma of the position, either axis
  bool has_altitude = false;  // SAR aircraft only
  double altitude = 0.0;      // [m] above sea level; 4094 means 4094 m or higher
  std::int64_t stamp_ns = 0;  // receive time of the report
  bool updated = false;       // reported since the last due()
};

// What became of a message.
enum class AisOutcome : std::uint8_t { Target, OwnShip, NotAShip, NoPosition, BadMmsi, OutOfRange };

class AisTargetTable {
public:
  AisTargetTable(const AisTargetConfig& cfg, const LocalFrame& frame);

  // A decoded message received at stamp_ns: a position report of a ship (types 1-3, 18, 19, 27)
  // updates her target; our own transponder (VDO), static data, base stations and aids to navigation
  // are not targets; a report without a position, with an invalid MMSI or beyond max_range is refused.
  AisOutcome update(const ais::Message& m, std::int64_t stamp_ns);
  // Forgets the ships not heard for forget_after at now_ns, then calls f(target, age [s]) for each
  // target reported since the last call, in the table's order.
  template <class F>
  void due(std::int64_t now_ns, F f);

  std::size_t size() const { return ships_.size(); }
  std::uint64_t evicted() const { return evicted_; }  // forgotten because the table was full
  void clear() { ships_.clear(); }

private:
  AisTargetConfig cfg_;
  LocalFrame frame_;
  std::unordered_map<std::uint32_t, AisTarget> ships_;
  std::uint64_t evicted_ = 0;
};

// [s] of a span in nanoseconds, rounded as ROS's Duration::toSec does (whole seconds plus 1e-9 x the
// remaining nanoseconds), so that ages match what a node computes from ros::Time.
double spanSeconds(std::int64_t ns);

// The due() of a target table: forgets the entries of `targets` (each with stamp_ns and updated) not
// heard for forget_after [s] at now_ns, then calls f(target, age [s]) for each entry updated since
// the last call, in the map's order, and clears its flag.
template <class Map, class F>
void dueTargets(Map& targets, std::int64_t now_ns, double forget_after, F f) {
  for (auto it = targets.begin(); it != targets.end();) {
    const double age = spanSeconds(now_ns - it->second.stamp_ns);
    if (age > forget_after) {
      it = targets.erase(it);
      continue;
    }
    if (it->second.updated) {
      it->second.updated = false;
      f(it->second, age);
    }
    ++it;
  }
}

template <class F>
void AisTargetTable::due(std::int64_t now_ns, F f) {
  dueTargets(ships_, now_ns, cfg_.forget_after, f);
}

// ---- Aids to navigation (message 21) ----

// A fixed or floating mark, or a virtual one (no physical mark: a wreck or a danger marked by AIS
// only), that a ship keeps clear of.
struct AidRecord {
  std::uint32_t mmsi = 0;
  std::string name;           // trimmed
  std::uint8_t aid_type = 0;  // ITU-R M.1371 table (ais::aidTypeText)
  bool virtual_aid = false;
  bool off_position = false;  // a floating aid reporting itself off its charted position
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] map frame
  double lat_deg = 0.0, lon_deg = 0.0;
  double to_bow = 0.0, to_stern = 0.0, to_port = 0.0, to_starboard = 0.0;  // [m], 0 = unknown
  std::int64_t stamp_ns = 0;                                               // receive time of the last report
};

struct AidTableConfig {
  double max_range = 200000.0;  // [m] aids farther from the map origin are refused
  std::size_t max_aids = 2000;  // aids remembered; a new one evicts the least recently heard
  // [s] an aid not heard for this long is forgotten. Aids report every 3 minutes (ITU-R M.1371); a
  // missed report or two must not make a mark vanish.
  double forget_after = 1800.0;
  void validate() const;
};

class AidTable {
public:
  AidTable(const AidTableConfig& cfg, const LocalFrame& frame);
  // A message 21 received at stamp_ns updates its aid (AisOutcome::Target); other messages are
  // NotAShip; a report without a position, with an invalid MMSI or beyond max_range is refused.
  AisOutcome update(const ais::Message& m, std::int64_t stamp_ns);
  // Forgets the aids not heard for forget_after at now_ns.
  void forget(std::int64_t now_ns);
  // Every aid known, by MMSI (a stable order for publishing).
  const std::map<std::uint32_t, AidRecord>& aids() const { return aids_; }
  std::size_t size() const { return aids_.size(); }
  std::uint64_t evicted() const { return evicted_; }
  void clear() { aids_.clear(); }

private:
  AidTableConfig cfg_;
  LocalFrame frame_;
  std::map<std::uint32_t, AidRecord> aids_;
  std::uint64_t evicted_ = 0;
};

}  // namespace asv
