// Rule 9 (COLREGs): a narrow channel or fairway, found from the chart's land and the route's corridor.
//
// The fairway at a point of a leg is the line across the leg's direction through that point, cut on
// each side by the first land (a static obstacle) or the leg's cross-track limit, whichever is nearer,
// probed up to a given distance. It is narrow when its width (port side + starboard side) is under a
// threshold (PlanFollowerConfig::narrow_fairway_width_m). A ship keeps to its starboard side (Rule
// 9(a)): in the starboard half, no nearer the starboard edge than her bank clearance.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "asv_core/world/obstacles.h"

namespace asv {

struct Fairway {
  double port = 0.0;       // [m] from the point to the port edge, across the leg
  double starboard = 0.0;  // [m] from the point to the starboard edge
  double width() const { return port + starboard; }
  // [m] signed offset of the fairway's middle from the point, positive to starboard
  double middle() const { return 0.5 * (starboard - port); }
};

// The fairway across the unit direction `along` at p: each side the distance to the first obstacle
// (0 when p is on land) or the corridor limit on that side (<= 0: none), at most `probe`.
Fairway fairwayAcross(const Eigen::Vector2d& p, const Eigen::Vector2d& along,
                      const std::vector<StaticObstacle>& obstacles, double port_limit, double starboard_limit,
                      double probe);

// The smallest bank clearance a ship keeps in a fairway: her land clearance, but at most a quarter of
// the width, so that a starboard lane is left in a channel narrower than four clearances (our choice).
double fairwayBankClearance(const Fairway& f, double land_clearance);

// Where across a narrow fairway a ship on the leg through p keeps (a signed offset from p, positive to
// starboard): p itself when it lies in the starboard lane, which runs from the middle of the starboard
// half out to the bank clearance (fairwayBankClearance) from the starboard edge; else the lane's nearer
// end.
double starboardLaneOffset(const Fairway& f, double land_clearance);

// The starboard edge a ship slows down at when no plan keeps every rule (Rules 9 and 8(e)): the bank
// clearance inside the starboard edge (a signed offset from p).
double starboardEdgeOffset(const Fairway& f, double land_clearance);

}  // namespace asv
