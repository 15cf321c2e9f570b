#include "asv_risk/ais_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_core/common/units.h>
#include <asv_ros/conversions.h>

#include "asv_risk/heartbeat.h"
#include "asv_risk/params.h"
#include "asv_risk/target_quality.h"

namespace asv_risk {

namespace {

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '@'))
    s.remove_suffix(1);
  return std::string(s);
}

}  // namespace

const char* toString(AisReject r) {
  switch (r) {
    case AisReject::kNoPosition:
      return "no position";
    case AisReject::kBadMmsi:
      return "invalid MMSI";
    case AisReject::kOutOfRange:
      return "beyond max_range";
    default:
      return "none";
  }
}

AisNodeParams loadAisParams(const ros::NodeHandle& pnh) {
  NmeaInputParams input;
  input.frame_id = "ais";
  return loadIngestionParams<asv::AisNodeConfig>(pnh, input, "config/ais_node.yaml");
}

AisNode::AisNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadAisParams(pnh)),
      map_origin_(nh, givenOrigin(params_)),
      frame_(map_origin_.get().lat_deg, map_origin_.get().lon_deg),
      framer_([this] {
        asv::nmea::FramerConfig c;
        c.max_length = params_.max_sentence_length;
        return c;
      }()),
      decoder_(params_.decoder),
      store_([this] {
        asv::ais::StaticStoreConfig c;
        c.max_ships = params_.max_static;
        return c;
      }()),
      table_(params_.targets, frame_),
      aux_(nh_, params_, frame_) {
  targets_pub_ = nh_.advertise<asv_msgs::TargetArray>("ais/targets", 10);
  // Each array holds what was reported since the last: nothing new, nothing to publish.
  lockstep_.every(
      1.0 / params_.publish_rate, [this] { publish(); }, true);
  lockstep_.every(
      1.0 / params_.publish_rate, [this] { aux_.publishSar(ros::Time::now()); }, true);
  lockstep_.every(params_.aids_period, [this] { aux_.publishAids(ros::Time::now()); });
  // Free-running only: in lockstep a node that stops stops the simulation (lockstep_timeout).
  if (!lockstep_.enabled())
    lockstep_.every(params_.heartbeat_period, [this] { heartbeat(); });
  updater_.setHardwareID("ais");
  updater_.add("ais input", this, &AisNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  last_sentence_ = diag_time_ = ros::WallTime::now();
  input_ = std::make_unique<NmeaInput>(
      nh_, params_.input, [this](const std::string& l, const ros::Time& t) { handleLine(l, t); }, &lockstep_);
  lockstep_.start();
  ROS_INFO("ais_node: input %s, origin %.6f %.6f, targets on %s in frame '%s'", input_->source().c_str(),
           map_origin_.get().lat_deg, map_origin_.get().lon_deg, targets_pub_.getTopic().c_str(),
           params_.frame_id.c_str());
}

void AisNode::checkClock() {
  asv_ros::resetOnClockJump(clock_, updater_, ros::Time::now(), [this] {
    std::string what = std::to_string(table_.size()) + " ships, the aids and the pending fragments forgotten";
    table_.clear();
    aux_.clear();
    decoder_.clearPending();
    return what;
  });
}

void AisNode::handleLine(const std::string& line, const ros::Time& stamp) {
  checkClock();
  const double now = stamp.toSec();
  framer_.frame(line, [&](const asv::nmea::Sentence& s) {
    last_sentence_ = ros::WallTime::now();
    const asv::ais::Status st = decoder_.feed(s, now, message_);
    if (st == asv::ais::Status::kNotAis)
      ++other_sentences_;
    else if (st == asv::ais::Status::kMessage)
      handleMessage(message_, stamp);
    else if (st != asv::ais::Status::kPending && st != asv::ais::Status::kUnsupportedType)
      ROS_WARN_THROTTLE(10.0, "ais_node: AIS sentence rejected (%s); counted in diagnostics",
                        asv::ais::statusText(st));
  });
}

void AisNode::reject(AisReject why, std::uint32_t mmsi) {
  ++rejected_[static_cast<std::size_t>(why)];
  ROS_WARN_THROTTLE(10.0, "ais_node: report of MMSI %u rejected (%s); counted in diagnostics", mmsi,
                    toString(why));
}

void AisNode::handleMessage(const asv::ais::Message& m, const ros::Time& stamp) {
  if (m.own_ship) {  // AIVDO: our own transponder, not a target
    ++own_ship_;
    return;
  }
  if (aux_.handle(m, decoder_.payload(), stamp))  // aids, SAR aircraft, safety texts, weather
    return;
  const bool had_static = store_.update(m) != nullptr;
  switch (table_.update(m, static_cast<std::int64_t>(stamp.toNSec()))) {
    case asv::AisOutcome::Target:
      ++reports_;
      break;
    case asv::AisOutcome::OwnShip:
      ++own_ship_;
      break;
    case asv::AisOutcome::NotAShip:  // static data only (5, 24), base stations (4), the other types
      if (!had_static)
        ++not_ships_;
      break;
    case asv::AisOutcome::NoPosition:
      reject(AisReject::kNoPosition, m.mmsi);
      break;
    case asv::AisOutcome::BadMmsi:
      reject(AisReject::kBadMmsi, m.mmsi);
      break;
    case asv::AisOutcome::OutOfRange:
      reject(AisReject::kOutOfRange, m.mmsi);
      break;
  }
}

void AisNode::mergeStatic(asv_msgs::Target& t) const {
  const asv::ais::ShipStatic* s = store_.find(t.mmsi);
  if (!s)
    return;
  if (s->has_name)
    t.name = trimmed(s->shipname.view());
  t.call_sign = trimmed(s->callsign.view());
  t.destination = trimmed(s->destination.view());
  if (s->has_type)
    t.ship_type = s->shiptype;
  if (s->has_dimensions) {
    t.to_bow = static_cast<float>(s->to_bow);
    t.to_stern = static_cast<float>(s->to_stern);
    t.to_port = static_cast<float>(s->to_port);
    t.to_starboard = static_cast<float>(s->to_starboard);
    t.length = static_cast<float>(s->length());
    t.beam = static_cast<float>(s->beam());
  }
}

void AisNode::publish() {
  checkClock();
  const ros::Time now = ros::Time::now();
  decoder_.expire(now.toSec());
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = params_.frame_id;
  table_.due(static_cast<std::int64_t>(now.toNSec()), [&](const asv::AisTarget& s, double age) {
    asv_msgs::Target t = aisTargetMsg(s);
    mergeStatic(t);  // static data may have arrived after the position
    t.age = std::max(0.0, age);
    arr.targets.push_back(std::move(t));
  });
  if (arr.targets.empty())
    return;
  lockstep_.publish(targets_pub_, arr);
  last_publish_ = now;
  ++published_;
}

void AisNode::heartbeat() {
  if (!input_ || !input_->linkUp())
    return;  // a link that is down is silence the tracker must see
  if (auto arr = heartbeatArray(ros::Time::now(), last_publish_, params_.heartbeat_period, params_.frame_id))
    lockstep_.publish(targets_pub_, *arr);
}

void AisNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  const ros::WallTime now = ros::WallTime::now();
  const double dt = std::max(1e-3, (now - diag_time_).toSec());
  const asv::ais::Counters& c = decoder_.counters();
  const std::uint64_t reassembly_drops = c.orphans + c.out_of_order + c.timeouts + c.evicted + c.restarted;
  std::uint64_t rejected_values = 0;
  for (std::size_t i = 1; i < static_cast<std::size_t>(AisReject::kCount); ++i) {
    stat.add(std::string("rejected: ") + toString(static_cast<AisReject>(i)), rejected_[i]);
    rejected_values += rejected_[i];
  }
  const std::uint64_t decode_errors =
      c.bad_fields + c.bad_fill + c.bad_armour + c.empty_payload + c.too_short + c.too_long + c.bad_part;
  const std::uint64_t rejected = framer_.totalRejected() + reassembly_drops + decode_errors + rejected_values;
  stat.add("sentences per second", (framer_.sentences() - diag_sentences_) / dt);
  addFramerStats(framer_, stat);
  stat.add("AIS sentences", c.sentences);
  stat.add("other sentences", other_sentences_);
  stat.add("messages decoded", c.messages);
  stat.add("reassembly drops", reassembly_drops);
  stat.add("fragments pending", decoder_.pendingCount());
  stat.add("clock jumps back (state reset)", clock_.jumps());
  stat.add("decode errors (fields, fill bits, armour, length, part)", decode_errors);
  stat.add("unsupported message types", c.unsupported);
  stat.add("rejected values", rejected_values);
  stat.add("position reports", reports_);
  stat.add("own ship (VDO) reports ignored", own_ship_);
  stat.add("other messages (base stations, binary, link management) not used", not_ships_);
  aux_.diagnose(stat);
  stat.add("targets known", table_.size());
  stat.add("targets forgotten (max_targets)", table_.evicted());
  stat.add("static records", store_.size());
  stat.add("target arrays published", published_);
  input_->diagnose(stat);
  const NmeaInputStats in = input_->stats();
  const double silent = (now - last_sentence_).toSec();
  if (!in.connected && !in.finished && params_.input.type != "topic")
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::ERROR, "input %s not connected",
                  input_->source().c_str());
  else if (silent > params_.silence_warning)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "no sentence for %.0f s", silent);
  else if (in.drops() > diag_drops_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN,
                  "%lu input lines dropped since the last report (overload)",
                  static_cast<unsigned long>(in.drops() - diag_drops_));
  else if (rejected > diag_rejected_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "%lu inputs rejected since the last report",
                  static_cast<unsigned long>(rejected - diag_rejected_));
  else
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::OK, "%zu targets", table_.size());
  diag_time_ = now;
  diag_sentences_ = framer_.sentences();
  diag_rejected_ = rejected;
  diag_drops_ = in.drops();
}

}  // namespace asv_risk
