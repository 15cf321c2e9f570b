#include "asv_core/tracking/plotter_output.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "asv_core/codec/autopilot.h"
#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/format.h"
#include "asv_core/common/units.h"

namespace asv {

namespace {

constexpr int kMaxTtmNumber = 99;  // TTM's target number field holds two digits

}  // namespace

void PlotterConfig::validate() const {
  static const std::set<std::string> known{"RMC", "HDT", "VDO", "TTM", "RTE"};
  if (!(rate > 0.0 && rate <= 10.0))
    throw std::invalid_argument("rate must be in (0, 10] Hz");
  if (own_mmsi > 999999999u)
    throw std::invalid_argument("own_mmsi must have at most 9 digits");
  if (!(stale_after > 0.0))
    throw std::invalid_argument("stale_after must be > 0 s");
  if (!(route_period > 0.0))
    throw std::invalid_argument("route_period must be > 0 s");
  if (max_targets > static_cast<std::size_t>(kMaxTtmNumber))
    throw std::invalid_argument("max_targets must be <= 99 (TTM numbers have two digits)");
  for (const std::string& s : sentences)
    if (!known.count(s))
      throw std::invalid_argument("sentences: unknown sentence '" + s + "' (RMC, HDT, VDO, TTM, RTE)");
}

PlotterConfig PlotterConfig::fromParams(const ParamMap& p) {
  PlotterConfig c;
  c.rate = p.getDouble("rate", c.rate);
  c.own_mmsi = static_cast<std::uint32_t>(p.getSize("own_mmsi", c.own_mmsi));
  c.max_targets = p.getSize("max_targets", c.max_targets);
  c.sentences = p.getStringList("sentences", c.sentences);
  c.forward_ais = p.getBool("forward_ais", c.forward_ais);
  c.stale_after = p.getDouble("stale_after", c.stale_after);
  c.route_period = p.getDouble("route_period", c.route_period);
  c.validate();
  return c;
}

bool PlotterConfig::sends(const std::string& type) const {
  return std::find(sentences.begin(), sentences.end(), type) != sentences.end();
}

PlotterOutput::PlotterOutput(const PlotterConfig& config, const LocalFrame& frame)
    : cfg_(config), frame_(frame) {
  cfg_.validate();
}

std::vector<std::string> PlotterOutput::sentences(const std::optional<PlotterOwn>& own,
                                                  const std::vector<PlotterTarget>& targets,
                                                  double unix_time) {
  ++period_;
  if (!own) {
    if (!cfg_.sends("RMC"))
      return {};
    gnss::RmcOut r;
    r.unix_time = unix_time;
    r.valid = false;
    return {gnss::encodeRmc(r)};
  }
  std::vector<std::string> out = ownShip(*own, unix_time);
  if (cfg_.sends("TTM"))
    for (std::string& s : ttm(*own, targets, unix_time))
      out.push_back(std::move(s));
  if (cfg_.sends("RTE") && !route_.empty() && unix_time - route_sent_ >= cfg_.route_period) {
    for (std::string& s : routeSentences())
      out.push_back(std::move(s));
    route_sent_ = unix_time;
  }
  return out;
}

void PlotterOutput::setRoute(const std::vector<Eigen::Vector2d>& route) {
  route_ = route;
  route_sent_ = -1e300;  // due in the next period
}

std::vector<std::string> PlotterOutput::routeSentences() const {
  std::vector<std::string> out, names;
  for (std::size_t k = 0; k < route_.size(); ++k) {
    names.push_back(strFormat("WP%03zu", k + 1));
    const GeoPoint g = frame_.toGeodetic(route_[k]);
    out.push_back(autopilot::encodeWpl(g.lat_deg, g.lon_deg, names.back()));
  }
  for (std::string& s : autopilot::encodeRte("ASV", names))
    out.push_back(std::move(s));
  return out;
}

std::vector<std::string> PlotterOutput::ownShip(const PlotterOwn& own, double unix_time) const {
  const GeoPoint g = frame_.toGeodetic(own.position);
  std::vector<std::string> out;
  if (cfg_.sends("RMC")) {
    gnss::RmcOut r;
    r.unix_time = unix_time;
    r.lat_deg = g.lat_deg;
    r.lon_deg = g.lon_deg;
    r.speed = own.speed;
    r.course = own.course;
    out.push_back(gnss::encodeRmc(r));
  }
  if (cfg_.sends("HDT") && own.heading)
    out.push_back(gnss::encodeHdt(*own.heading));
  if (cfg_.sends("VDO") && cfg_.own_mmsi != 0) {
    ais::PositionReportA a;
    a.status = 0;  // under way using engine: the stack steers her
    a.lat = ais::rawLat(g.lat_deg);
    a.lon = ais::rawLon(g.lon_deg);
    a.speed = ais::rawSpeed(own.speed);
    a.course = ais::rawCourse(own.course);
    a.heading = ais::rawHeading(own.heading);
    a.second = static_cast<std::uint8_t>(static_cast<long long>(std::floor(unix_time)) % 60);
    for (std::string& s :
         ais::toSentences(ais::encodePositionA(1, cfg_.own_mmsi, a), 'A', 0, "AI", 60, "VDO"))
      out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> PlotterOutput::ttm(const PlotterOwn& own, std::vector<PlotterTarget> targets,
                                            double unix_time) {
  std::sort(targets.begin(), targets.end(), [&](const PlotterTarget& a, const PlotterTarget& b) {
    return (a.position - own.position).squaredNorm() < (b.position - own.position).squaredNorm();
  });
  if (targets.size() > cfg_.max_targets)
    targets.resize(cfg_.max_targets);
  std::set<std::string> sent;
  for (const PlotterTarget& t : targets)
    sent.insert(t.id);
  for (auto it = numbers_.begin(); it != numbers_.end();)  // free the numbers of targets not sent
    if (sent.count(it->first)) {
      ++it;
    } else {
      freed_[it->second] = period_;
      it = numbers_.erase(it);
    }
  const double seconds_of_day = std::fmod(std::fmod(unix_time, 86400.0) + 86400.0, 86400.0);
  std::vector<std::string> out;
  for (const PlotterTarget& t : targets) {
    arpa::TtmOut m;
    m.number = numberOf(t.id);
    m.distance = (t.position - own.position).norm();
    m.bearing = trueBearing(own.position, t.position);
    m.speed = t.speed;
    m.course = t.course;
    m.cpa = t.dcpa;
    m.tcpa = t.tcpa;
    m.name = t.name;
    m.utc_seconds_of_day = seconds_of_day;
    m.acquisition = t.reported ? 'R' : 'A';
    out.push_back(arpa::encodeTtm(m, "EC"));
  }
  return out;
}

// The number a target keeps: its own, else the lowest never used, else the one freed longest ago.
int PlotterOutput::numberOf(const std::string& id) {
  const auto it = numbers_.find(id);
  if (it != numbers_.end())
    return it->second;
  std::set<int> used;
  for (const auto& [_, n] : numbers_)
    used.insert(n);
  int best = 0;
  for (int n = 1; n <= kMaxTtmNumber; ++n) {
    if (used.count(n))
      continue;
    const auto f = freed_.find(n);
    if (f == freed_.end()) {
      best = n;
      break;
    }
    if (best == 0 || f->second < freed_[best])
      best = n;
  }
  freed_.erase(best);
  numbers_[id] = best;
  return best;
}

}  // namespace asv
