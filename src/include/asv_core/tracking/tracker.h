// Target tracker: fuses AIS and ARPA reports of other ships into one track per ship, dead-reckons
// between reports, coasts and then drops stale tracks. ROS-free; asv_risk/tracker is its thin node.
//
// State per track: ENU position and velocity with one isotropic variance each (per axis), updated by
// a scalar Kalman filter per sensor report (constant-velocity model, white acceleration noise). The
// cross-covariance of position and velocity is ignored: the filter only has to weigh a precise AIS
// fix against a coarse radar fix, not to smooth a noisy sensor.
//
// Association (documented in asv_risk/config/tracker.yaml and README.md):
//  1. By identity: an AIS report goes to the track holding its MMSI, an ARPA report to the track
//     holding its radar target number. Once an ARPA track is paired with an MMSI the pairing sticks
//     (track-to-track association) until a sensor's part of the track expires or the radar target
//     keeps disagreeing with the AIS (TrackerConfig::split_after reports outside the gate).
//  2. Otherwise nearest neighbour among the tracks of the other sensor that are not yet paired (an
//     AIS report looks at ARPA-only tracks, an ARPA report at AIS-only tracks): the track whose
//     position, dead-reckoned to the report time, is closest, within the position gate
//     max(gate_min, gate_sigmas * sqrt(P_track + R_report)) and, when both have a velocity, within
//     the velocity gate |v_track - v_report| <= velocity_gate.
//  3. Otherwise a new track.
//  4. At every maintain(): an ARPA-only and an AIS-only track that pass both gates at that time are
//     merged (nearest first), so two tracks of one ship do not live side by side when the second
//     sensor's first report missed the gate.
//
// Ages (per sensor part of a track; the track lives while one part lives): a part is fresh until
// coast_after, coasting (dead-reckoned, quality falling) until drop_after, then dropped. AIS class A
// parts use ais_a, class B ais_b, and any AIS part slower than slow_speed uses ais_slow (ITU-R
// M.1371 reporting intervals: class A 2-10 s under way, 3 min at anchor; class B 30 s, 3 min below
// 2 kn). ARPA parts use arpa (a radar scan is 2-3 s).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace asv {

enum class TrackSource : std::uint8_t { kUnknown = 0, kAis = 1, kArpa = 2, kFused = 3 };
enum class AisClass : std::uint8_t { kNone = 0, kA = 1, kB = 2 };

const char* trackSourceText(TrackSource s);

// Ages of one kind of report [s].
struct TrackAges {
  double coast_after = 30.0;  // no report for this long: the part is coasting
  double drop_after = 120.0;  // no report for this long: the part is dropped
};

struct TrackerConfig {
  double gate_min = 200.0;           // [m] smallest position gate radius
  double gate_sigmas = 3.0;          // position gate in standard deviations of the predicted difference
  double velocity_gate = 2.5;        // [m/s] largest velocity difference of one ship (about 5 kn)
  int split_after = 3;               // paired ARPA reports outside the gate in a row that break the pairing
  double accel_sigma = 0.1;          // [m/s^2] white acceleration noise of the constant-velocity model
  double slow_speed = 1.5;           // [m/s] AIS parts slower than this use ais_slow (3 kn: ITU slow rate)
  std::size_t max_tracks = 1000;     // reports that would open a track beyond this are rejected
  TrackAges ais_a{30.0, 120.0};      // 3 missed 10 s reports; dropped after 2 min
  TrackAges ais_b{90.0, 360.0};      // 3 missed 30 s reports; dropped after 6 min
  TrackAges ais_slow{360.0, 600.0};  // 2 missed 3 min reports; dropped after 10 min
  TrackAges arpa{10.0, 60.0};        // about 3 missed radar scans; dropped after 1 min

  // Throws std::invalid_argument naming the field when a value is out of range.
  void validate() const;
};

// One report of one ship by one sensor, in the local ENU frame.
struct TrackReport {
  TrackSource source = TrackSource::kAis;  // kAis or kArpa
  std::uint32_t mmsi = 0;                  // AIS: required (1..999999999)
  int arpa_number = -1;                    // ARPA: required (>= 0)
  AisClass ais_class = AisClass::kNone;
  double time = 0.0;                                   // [s] time of the report
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
  double position_variance = 100.0;                    // [m^2] per axis
  bool has_velocity = false;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s] ENU over ground
  double velocity_variance = 0.04;                     // [m^2/s^2] per axis
  double quality = 100.0;                              // 0-100: the sensor's own confidence
};

struct Track {
  std::uint64_t id = 0;    // unique, never reused
  std::uint32_t mmsi = 0;  // 0 = none
  int arpa_number = -1;    // -1 = none
  AisClass ais_class = AisClass::kNone;
  double time = 0.0;  // [s] time of the state
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  bool has_velocity = false;
  double position_variance = 0.0;                               // [m^2] per axis, at `time`
  double velocity_variance = 0.0;                               // [m^2/s^2] per axis, at `time`
  double last_ais = -std::numeric_limits<double>::infinity();   // [s] last AIS report
  double last_arpa = -std::numeric_limits<double>::infinity();  // [s] last ARPA report
  double ais_quality = 0.0, arpa_quality = 0.0;
  double first_seen = 0.0;
  int arpa_mismatches = 0;  // paired ARPA reports outside the gate in a row
};

// A track dead-reckoned to a given time.
struct TrackEstimate {
  std::uint64_t id = 0;
  std::uint32_t mmsi = 0;
  int arpa_number = -1;
  AisClass ais_class = AisClass::kNone;
  TrackSource source = TrackSource::kUnknown;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU at the estimate time
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s]; zero when !has_velocity
  bool has_velocity = false;
  double position_variance = 0.0;  // [m^2] per axis
  double last_report = 0.0;        // [s] time of the last report of any sensor
  double age = 0.0;                // [s] since the last report
  bool coasting = false;           // no part of the track is fresh
  double quality = 0.0;            // 0-100
};

enum class UpdateResult : std::uint8_t {
  kUpdated = 0,  // matched by MMSI / radar number
  kAssociated,   // joined a track of the other sensor by gating
  kCreated,      // opened a new track
  kOld,          // not newer than the last report of this sensor for this ship (ignored)
  kInvalid,      // non-finite value, missing id, or wrong source
  kFull,         // would open a track beyond max_tracks
  kCount
};

const char* updateResultText(UpdateResult r);

struct TrackerCounters {
  std::uint64_t reports = 0;
  std::uint64_t results[static_cast<std::size_t>(UpdateResult::kCount)] = {};
  std::uint64_t merged = 0;   // track-to-track merges in maintain()
  std::uint64_t split = 0;    // ARPA pairings broken by disagreement
  std::uint64_t dropped = 0;  // tracks dropped as stale
};

class Tracker {
public:
  explicit Tracker(const TrackerConfig& config = TrackerConfig());

  UpdateResult update(const TrackReport& report);
  // Track-to-track association, expiry of sensor parts and of whole tracks at `now` [s]. Returns the
  // number of tracks dropped.
  std::size_t maintain(double now);
  // Every track dead-reckoned to `now` (straight line at the last velocity), in creation order.
  std::vector<TrackEstimate> estimates(double now) const;
  TrackEstimate estimate(const Track& t, double now) const;
  // Drops every track (the clock went backwards: their times are in the future). Counters and track
  // ids carry on, so an id is never reused.
  void clear() { tracks_.clear(); }

  const std::vector<Track>& tracks() const { return tracks_; }
  const TrackerCounters& counters() const { return counters_; }
  const TrackerConfig& config() const { return config_; }

  // Ages that apply to the AIS part of a track (class and speed).
  const TrackAges& aisAges(const Track& t) const;

private:
  void predict(Track& t, double to) const;
  void correct(Track& t, const TrackReport& r) const;
  Track* findByMmsi(std::uint32_t mmsi);
  Track* findByArpa(int number);
  Track* nearest(const TrackReport& r);
  bool gates(const Track& predicted, const TrackReport& r, double* distance) const;
  bool aisAlive(const Track& t, double now) const;
  bool arpaAlive(const Track& t, double now) const;
  UpdateResult count(UpdateResult r);
  static bool allFiniteReport(const TrackReport& r);

  TrackerConfig config_;
  std::vector<Track> tracks_;
  std::uint64_t next_id_ = 1;
  TrackerCounters counters_;
};

}  // namespace asv
