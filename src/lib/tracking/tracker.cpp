#include "asv_core/tracking/tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace asv {

namespace {

constexpr std::uint32_t kMaxMmsi = 999999999;

void checkAges(const TrackAges& a, const char* name) {
  if (!(a.coast_after > 0.0 && a.drop_after > a.coast_after && std::isfinite(a.drop_after)))
    throw std::invalid_argument(std::string("tracker: ") + name +
                                " ages must satisfy 0 < coast_after < drop_after < inf");
}

// Quality of one sensor part: its report quality while fresh, then falling linearly from half of it
// to 0 over the coasting time.
double partQuality(double quality, double age, const TrackAges& ages) {
  if (age <= ages.coast_after)
    return quality;
  if (age >= ages.drop_after)
    return 0.0;
  return 0.5 * quality * (ages.drop_after - age) / (ages.drop_after - ages.coast_after);
}

}  // namespace

const char* trackSourceText(TrackSource s) {
  switch (s) {
    case TrackSource::kAis:
      return "AIS";
    case TrackSource::kArpa:
      return "ARPA";
    case TrackSource::kFused:
      return "FUSED";
    default:
      return "unknown";
  }
}

const char* updateResultText(UpdateResult r) {
  static const char* const kText[] = {"updated", "associated", "created", "old", "invalid", "full"};
  const auto i = static_cast<std::size_t>(r);
  return i < static_cast<std::size_t>(UpdateResult::kCount) ? kText[i] : "?";
}

void TrackerConfig::validate() const {
  if (!(gate_min > 0.0 && std::isfinite(gate_min)))
    throw std::invalid_argument("tracker: gate_min must be > 0 m");
  if (!(gate_sigmas > 0.0 && std::isfinite(gate_sigmas)))
    throw std::invalid_argument("tracker: gate_sigmas must be > 0");
  if (!(velocity_gate > 0.0 && std::isfinite(velocity_gate)))
    throw std::invalid_argument("tracker: velocity_gate must be > 0 m/s");
  if (split_after < 1)
    throw std::invalid_argument("tracker: split_after must be >= 1");
  if (!(accel_sigma >= 0.0 && std::isfinite(accel_sigma)))
    throw std::invalid_argument("tracker: accel_sigma must be >= 0 m/s^2");
  if (!(slow_speed >= 0.0 && std::isfinite(slow_speed)))
    throw std::invalid_argument("tracker: slow_speed must be >= 0 m/s");
  if (max_tracks < 1)
    throw std::invalid_argument("tracker: max_tracks must be >= 1");
  checkAges(ais_a, "ais_a");
  checkAges(ais_b, "ais_b");
  checkAges(ais_slow, "ais_slow");
  checkAges(arpa, "arpa");
}

Tracker::Tracker(const TrackerConfig& config) : config_(config) {
  config_.validate();
}

UpdateResult Tracker::count(UpdateResult r) {
  ++counters_.results[static_cast<std::size_t>(r)];
  return r;
}

const TrackAges& Tracker::aisAges(const Track& t) const {
  if (t.has_velocity && t.velocity.norm() < config_.slow_speed)
    return config_.ais_slow;
  return t.ais_class == AisClass::kB ? config_.ais_b : config_.ais_a;
}

bool Tracker::aisAlive(const Track& t, double now) const {
  return t.mmsi != 0 && std::isfinite(t.last_ais) && now - t.last_ais <= aisAges(t).drop_after;
}

bool Tracker::arpaAlive(const Track& t, double now) const {
  return t.arpa_number >= 0 && std::isfinite(t.last_arpa) && now - t.last_arpa <= config_.arpa.drop_after;
}

void Tracker::predict(Track& t, double to) const {
  const double dt = to - t.time;
  if (dt == 0.0)
    return;
  if (t.has_velocity)
    t.position += t.velocity * dt;
  const double q = config_.accel_sigma * config_.accel_sigma;
  const double dt2 = dt * dt;
  t.position_variance += t.velocity_variance * dt2 + q * dt2 * dt2 / 4.0;
  if (t.has_velocity)
    t.velocity_variance += q * dt2;
  t.time = to;
}

void Tracker::correct(Track& t, const TrackReport& r) const {
  const double k = t.position_variance / (t.position_variance + r.position_variance);
  t.position += k * (r.position - t.position);
  t.position_variance *= (1.0 - k);
  if (!r.has_velocity)
    return;
  if (!t.has_velocity) {
    t.velocity = r.velocity;
    t.velocity_variance = r.velocity_variance;
    t.has_velocity = true;
    return;
  }
  const double kv = t.velocity_variance / (t.velocity_variance + r.velocity_variance);
  t.velocity += kv * (r.velocity - t.velocity);
  t.velocity_variance *= (1.0 - kv);
}

Track* Tracker::findByMmsi(std::uint32_t mmsi) {
  for (Track& t : tracks_)
    if (t.mmsi == mmsi)
      return &t;
  return nullptr;
}

Track* Tracker::findByArpa(int number) {
  for (Track& t : tracks_)
    if (t.arpa_number == number)
      return &t;
  return nullptr;
}

bool Tracker::gates(const Track& predicted, const TrackReport& r, double* distance) const {
  const double d = (predicted.position - r.position).norm();
  const double gate = std::max(
      config_.gate_min, config_.gate_sigmas * std::sqrt(predicted.position_variance + r.position_variance));
  if (distance)
    *distance = d;
  if (!(d <= gate))
    return false;
  if (predicted.has_velocity && r.has_velocity &&
      !((predicted.velocity - r.velocity).norm() <= config_.velocity_gate))
    return false;
  return true;
}

Track* Tracker::nearest(const TrackReport& r) {
  Track* best = nullptr;
  double best_d = 0.0;
  for (Track& t : tracks_) {
    // Only the other sensor's unpaired tracks: an MMSI never moves to another MMSI's track.
    const bool candidate = r.source == TrackSource::kAis ? (t.mmsi == 0 && t.arpa_number >= 0)
                                                         : (t.mmsi != 0 && t.arpa_number < 0);
    if (!candidate)
      continue;
    Track p = t;
    predict(p, r.time);
    double d = 0.0;
    if (gates(p, r, &d) && (!best || d < best_d)) {
      best = &t;
      best_d = d;
    }
  }
  return best;
}

UpdateResult Tracker::update(const TrackReport& r) {
  ++counters_.reports;
  const bool ais = r.source == TrackSource::kAis;
  if ((!ais && r.source != TrackSource::kArpa) || (ais && (r.mmsi == 0 || r.mmsi > kMaxMmsi)) ||
      (!ais && r.arpa_number < 0) || !allFiniteReport(r))
    return count(UpdateResult::kInvalid);

  Track* t = ais ? findByMmsi(r.mmsi) : findByArpa(r.arpa_number);
  UpdateResult result = UpdateResult::kUpdated;
  if (t) {
    if (r.time <= (ais ? t->last_ais : t->last_arpa))
      return count(UpdateResult::kOld);
    if (!ais && t->mmsi != 0 && aisAlive(*t, r.time)) {
      // A paired radar target must keep agreeing with the AIS ship it was paired with.
      Track p = *t;
      predict(p, r.time);
      if (!gates(p, r, nullptr)) {
        if (++t->arpa_mismatches >= config_.split_after) {
          t->arpa_number = -1;
          t->last_arpa = -std::numeric_limits<double>::infinity();
          t->arpa_mismatches = 0;
          ++counters_.split;
          t = nullptr;  // the radar target becomes a track of its own below
        } else {
          t->last_arpa = r.time;  // still alive, but it does not pull the AIS track away
          return count(UpdateResult::kUpdated);
        }
      } else {
        t->arpa_mismatches = 0;
      }
    }
  } else {
    t = nearest(r);
    if (t) {
      result = UpdateResult::kAssociated;
      if (ais)
        t->mmsi = r.mmsi;
      else
        t->arpa_number = r.arpa_number;
    }
  }

  if (!t) {
    if (tracks_.size() >= config_.max_tracks)
      return count(UpdateResult::kFull);
    Track n;
    n.id = next_id_++;
    n.time = r.time;
    n.first_seen = r.time;
    n.position = r.position;
    n.position_variance = r.position_variance;
    n.has_velocity = r.has_velocity;
    if (r.has_velocity) {
      n.velocity = r.velocity;
      n.velocity_variance = r.velocity_variance;
    }
    if (ais)
      n.mmsi = r.mmsi;
    else
      n.arpa_number = r.arpa_number;
    tracks_.push_back(n);
    t = &tracks_.back();
    result = UpdateResult::kCreated;
  } else {
    predict(*t, r.time);
    correct(*t, r);
  }
  if (ais) {
    t->last_ais = r.time;
    t->ais_quality = r.quality;
    if (r.ais_class != AisClass::kNone)
      t->ais_class = r.ais_class;
  } else {
    t->last_arpa = r.time;
    t->arpa_quality = r.quality;
  }
  return count(result);
}

bool Tracker::allFiniteReport(const TrackReport& r) {
  return std::isfinite(r.time) && r.position.allFinite() && std::isfinite(r.position_variance) &&
         r.position_variance > 0.0 && std::isfinite(r.quality) && r.quality >= 0.0 && r.quality <= 100.0 &&
         (!r.has_velocity ||
          (r.velocity.allFinite() && std::isfinite(r.velocity_variance) && r.velocity_variance > 0.0));
}

std::size_t Tracker::maintain(double now) {
  // Sensor parts that expired: a radar reuses target numbers, so an expired number is released.
  for (Track& t : tracks_) {
    if (t.arpa_number >= 0 && !arpaAlive(t, now)) {
      t.arpa_number = -1;
      t.arpa_mismatches = 0;
    }
  }
  const std::size_t before = tracks_.size();
  tracks_.erase(std::remove_if(tracks_.begin(), tracks_.end(),
                               [&](const Track& t) { return !aisAlive(t, now) && !arpaAlive(t, now); }),
                tracks_.end());
  const std::size_t dropped = before - tracks_.size();
  counters_.dropped += dropped;

  // Track-to-track association: nearest pairs first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;  // distance, ARPA track, AIS track
  for (std::size_t a = 0; a < tracks_.size(); ++a) {
    if (tracks_[a].mmsi != 0 || tracks_[a].arpa_number < 0)
      continue;
    Track pa = tracks_[a];
    predict(pa, now);
    TrackReport r;
    r.source = TrackSource::kArpa;
    r.time = now;
    r.position = pa.position;
    r.position_variance = std::max(pa.position_variance, 1e-6);
    r.has_velocity = pa.has_velocity;
    r.velocity = pa.velocity;
    for (std::size_t b = 0; b < tracks_.size(); ++b) {
      if (tracks_[b].mmsi == 0 || tracks_[b].arpa_number >= 0 || !aisAlive(tracks_[b], now))
        continue;
      Track pb = tracks_[b];
      predict(pb, now);
      double d = 0.0;
      if (gates(pb, r, &d))
        pairs.emplace_back(d, a, b);
    }
  }
  if (pairs.empty())
    return dropped;
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used(tracks_.size(), false), erase(tracks_.size(), false);
  for (const auto& [d, a, b] : pairs) {
    (void)d;
    if (used[a] || used[b])
      continue;
    used[a] = used[b] = true;
    erase[a] = true;
    tracks_[b].arpa_number = tracks_[a].arpa_number;
    tracks_[b].last_arpa = tracks_[a].last_arpa;
    tracks_[b].arpa_quality = tracks_[a].arpa_quality;
    tracks_[b].arpa_mismatches = 0;
    ++counters_.merged;
  }
  std::size_t w = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i)
    if (!erase[i])
      tracks_[w++] = tracks_[i];
  tracks_.resize(w);
  return dropped;
}

TrackEstimate Tracker::estimate(const Track& t, double now) const {
  Track p = t;
  if (now > p.time)
    predict(p, now);
  TrackEstimate e;
  e.id = t.id;
  e.mmsi = t.mmsi;
  e.arpa_number = t.arpa_number;
  e.ais_class = t.ais_class;
  e.position = p.position;
  e.has_velocity = p.has_velocity;
  e.velocity = p.has_velocity ? p.velocity : Eigen::Vector2d::Zero();
  e.position_variance = p.position_variance;
  const bool has_ais = t.mmsi != 0 && std::isfinite(t.last_ais);
  const bool has_arpa = t.arpa_number >= 0 && std::isfinite(t.last_arpa);
  e.last_report = std::max(has_ais ? t.last_ais : -std::numeric_limits<double>::infinity(),
                           has_arpa ? t.last_arpa : -std::numeric_limits<double>::infinity());
  if (!std::isfinite(e.last_report))
    e.last_report = t.time;
  e.age = std::max(0.0, now - e.last_report);
  const bool ais_alive = aisAlive(t, now), arpa_alive = arpaAlive(t, now);
  e.source = ais_alive && arpa_alive ? TrackSource::kFused
             : ais_alive             ? TrackSource::kAis
             : arpa_alive            ? TrackSource::kArpa
                                     : TrackSource::kUnknown;
  const TrackAges& aa = aisAges(t);
  bool fresh = false;
  if (ais_alive) {
    const double age = std::max(0.0, now - t.last_ais);
    fresh = fresh || age <= aa.coast_after;
    e.quality = std::max(e.quality, partQuality(t.ais_quality, age, aa));
  }
  if (arpa_alive) {
    const double age = std::max(0.0, now - t.last_arpa);
    fresh = fresh || age <= config_.arpa.coast_after;
    e.quality = std::max(e.quality, partQuality(t.arpa_quality, age, config_.arpa));
  }
  e.coasting = !fresh;
  return e;
}

std::vector<TrackEstimate> Tracker::estimates(double now) const {
  std::vector<TrackEstimate> out;
  out.reserve(tracks_.size());
  for (const Track& t : tracks_)
    out.push_back(estimate(t, now));
  return out;
}

}  // namespace asv
