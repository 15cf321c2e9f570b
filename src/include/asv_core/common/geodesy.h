// Geodetic <-> local ENU conversion through GeographicLib::LocalCartesian (WGS84), around a scenario
// origin. Never a hand-made flat-earth formula (README.md, Conventions).
#pragma once

#include <memory>
#include <optional>

#include <Eigen/Core>

#include "asv_core/common/param_map.h"

namespace GeographicLib {
class LocalCartesian;
}

namespace asv {

struct GeoPoint {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
};

class LocalFrame {
public:
  // Origin of the local frame on the WGS84 ellipsoid surface (height 0). Throws std::invalid_argument
  // for a latitude outside [-90, 90], a longitude outside [-180, 180] or a non-finite value.
  LocalFrame(double origin_lat_deg, double origin_lon_deg);
  LocalFrame(const LocalFrame& other);
  LocalFrame& operator=(const LocalFrame& other);
  ~LocalFrame();

  GeoPoint origin() const { return origin_; }

  // Local ENU metres (x east, y north) of a geodetic point at sea level.
  Eigen::Vector2d toLocal(double lat_deg, double lon_deg) const;
  Eigen::Vector2d toLocal(const GeoPoint& p) const { return toLocal(p.lat_deg, p.lon_deg); }
  // Geodetic point of local ENU metres, at sea level.
  GeoPoint toGeodetic(const Eigen::Vector2d& enu) const;

private:
  GeoPoint origin_;
  std::unique_ptr<GeographicLib::LocalCartesian> proj_;
};

// True when lat/lon are finite and in range; AIS "not available" (91, 181) is out of range.
bool validLatLon(double lat_deg, double lon_deg);

// A node's own map origin from its keys origin_lat_deg and origin_lon_deg: both (a valid position) or
// neither (empty: the node takes the run's /map_origin). Half an origin, or one off the globe, is
// std::invalid_argument naming the keys.
std::optional<GeoPoint> originFromParams(const ParamMap& p);

}  // namespace asv
