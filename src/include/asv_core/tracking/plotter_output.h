// What a chart plotter (OpenCPN, or any ECS reading NMEA 0183) needs to show the situation the stack
// sees: the own ship as RMC (position, course and speed over ground), HDT (heading) and her
// transponder's VDO (AIS type 1), and each tracked target as TTM (range and bearing from her, course,
// speed, and the CPA and TCPA of the risk picture). plotter_node's logic, free of ROS.
//
// Rules: targets nearest first, at most max_targets; each keeps its TTM number (1-99) while it is sent,
// and a number freed by a target that went is given again only after every unused one (a plotter
// keeps a lost target's number for a while); TTM's acquisition is R (reported) for an AIS-only track,
// A (automatic) otherwise. No own position: RMC status V and nothing else, so the plotter shows the
// loss instead of the last position.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geodesy.h"
#include "asv_core/common/param_map.h"

namespace asv {

// plotter_node's keys (asv_risk/config/plotter_node.yaml documents each).
struct PlotterConfig {
  double rate = 1.0;             // [Hz] one set of sentences per period
  std::uint32_t own_mmsi = 0;    // in her VDO; 0: no VDO
  std::size_t max_targets = 50;  // TTM per period, nearest first (<= 99)
  std::vector<std::string> sentences{"RMC", "HDT", "VDO", "TTM", "RTE"};  // which to send (RTE: WPL + RTE)
  bool forward_ais = true;   // also forward the AIVDM/AIVDO sentences read on nmea_in (the traffic's reports)
  double stale_after = 2.0;  // [s] own odometry or a target array older than this is not sent as current
  double route_period = 10.0;  // [s] the route (WPL, RTE) is sent when it changes and then this often
  void validate() const;
  static PlotterConfig fromParams(const ParamMap& p);
  bool sends(const std::string& type) const;
};

struct PlotterOwn {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] map (ENU)
  double course = 0.0, speed = 0.0;                    // over ground [rad, m/s]
  std::optional<double> heading;                       // [rad] true
};

struct PlotterTarget {
  std::string id;  // the track's, stable
  std::string name;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] map (ENU)
  double course = 0.0, speed = 0.0;                    // over ground [rad, m/s]
  std::optional<double> dcpa, tcpa;                    // [m, s] from the risk picture
  bool reported = false;                               // an AIS-only track (TTM acquisition R)
};

class PlotterOutput {
public:
  PlotterOutput(const PlotterConfig& config, const LocalFrame& frame);

  // The period's sentences at `unix_time` [s, UTC]: the own ship's (RMC V alone without `own`), then
  // the targets' TTM, and the route when due.
  std::vector<std::string> sentences(const std::optional<PlotterOwn>& own,
                                     const std::vector<PlotterTarget>& targets, double unix_time);
  // The voyage plan the ship sails (map positions; empty: none): sent as WPL (waypoints WP001, ...) and
  // RTE (route "ASV", complete) in the next period and every route_period, so that the plotter shows
  // and keeps it.
  void setRoute(const std::vector<Eigen::Vector2d>& route);

private:
  std::vector<std::string> ownShip(const PlotterOwn& own, double unix_time) const;
  std::vector<std::string> ttm(const PlotterOwn& own, std::vector<PlotterTarget> targets, double unix_time);
  int numberOf(const std::string& id);
  std::vector<std::string> routeSentences() const;

  PlotterConfig cfg_;
  LocalFrame frame_;
  std::map<std::string, int> numbers_;  // track id -> TTM number
  std::map<int, std::uint64_t> freed_;  // TTM number -> period it was freed
  std::uint64_t period_ = 0;
  std::vector<Eigen::Vector2d> route_;
  double route_sent_ = -1e300;  // [s] unix time the route was last sent (-1e300: due)
};

}  // namespace asv
