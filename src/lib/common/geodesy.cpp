#include "asv_core/common/geodesy.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <GeographicLib/LocalCartesian.hpp>

namespace asv {

bool validLatLon(double lat_deg, double lon_deg) {
  return std::isfinite(lat_deg) && std::isfinite(lon_deg) && std::fabs(lat_deg) <= 90.0 &&
         std::fabs(lon_deg) <= 180.0;
}

LocalFrame::LocalFrame(double origin_lat_deg, double origin_lon_deg) {
  if (!validLatLon(origin_lat_deg, origin_lon_deg))
    throw std::invalid_argument("local frame origin out of range: lat " + std::to_string(origin_lat_deg) +
                                " deg, lon " + std::to_string(origin_lon_deg) + " deg");
  origin_ = {origin_lat_deg, origin_lon_deg};
  proj_ = std::make_unique<GeographicLib::LocalCartesian>(origin_lat_deg, origin_lon_deg, 0.0);
}

LocalFrame::LocalFrame(const LocalFrame& other)
    : origin_(other.origin_), proj_(std::make_unique<GeographicLib::LocalCartesian>(*other.proj_)) {}

LocalFrame& LocalFrame::operator=(const LocalFrame& other) {
  if (this != &other) {
    origin_ = other.origin_;
    proj_ = std::make_unique<GeographicLib::LocalCartesian>(*other.proj_);
  }
  return *this;
}

LocalFrame::~LocalFrame() = default;

Eigen::Vector2d LocalFrame::toLocal(double lat_deg, double lon_deg) const {
  double x, y, z;
  proj_->Forward(lat_deg, lon_deg, 0.0, x, y, z);
  return {x, y};
}

GeoPoint LocalFrame::toGeodetic(const Eigen::Vector2d& enu) const {
  // The local tangent plane dips below the ellipsoid away from the origin; a point given in the
  // plane at z = 0 is therefore slightly above sea level. Project back along the vertical by
  // solving for the z at which the geodetic height is zero (two fixed-point steps reach < 1e-9 m).
  double lat, lon, h, z = 0.0;
  for (int i = 0; i < 3; ++i) {
    proj_->Reverse(enu.x(), enu.y(), z, lat, lon, h);
    z -= h;
  }
  proj_->Reverse(enu.x(), enu.y(), z, lat, lon, h);
  return {lat, lon};
}

std::optional<GeoPoint> originFromParams(const ParamMap& p) {
  if (p.has("origin_lat_deg") != p.has("origin_lon_deg"))
    throw std::invalid_argument("give both origin_lat_deg and origin_lon_deg (origin of the map frame)");
  if (!p.has("origin_lat_deg"))
    return std::nullopt;
  const GeoPoint o{p.getDouble("origin_lat_deg", 0.0), p.getDouble("origin_lon_deg", 0.0)};
  if (!validLatLon(o.lat_deg, o.lon_deg))
    throw std::invalid_argument("origin_lat_deg/origin_lon_deg out of range");
  return o;
}

}  // namespace asv
