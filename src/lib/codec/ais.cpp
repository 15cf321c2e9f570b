#include "asv_core/codec/ais.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {
namespace ais {

// ---- Payload ----

char Payload::sixbitChar(std::uint32_t v) {
  static constexpr char kChars[65] = "@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_ !\"#$%&'()*+,-./0123456789:;<=>?";
  return kChars[v & 63u];
}

bool Payload::append(std::string_view armoured) {
  if (nbits_ + armoured.size() * 6 > kMaxPayloadBits)
    return false;
  std::size_t b = nbits_;
  for (char ch : armoured) {
    unsigned c = static_cast<unsigned char>(ch);
    // Armour alphabet: '0'..'W' (0..39) and '`'..'w' (40..63).
    if (c < 48 || c > 119 || (c > 87 && c < 96))
      return false;
    unsigned v = c - 48;
    if (v > 40)
      v -= 8;
    const std::size_t i = b >> 3;
    const unsigned off = static_cast<unsigned>(b & 7);
    const unsigned w = v << (10 - off);              // the 6 bits placed in a 16-bit window at `off`
    const unsigned keep = (0xFF00u >> off) & 0xFFu;  // bits of byte i already written
    bytes_[i] = static_cast<std::uint8_t>((bytes_[i] & keep) | (w >> 8));
    bytes_[i + 1] = static_cast<std::uint8_t>(w & 0xFF);
    b += 6;
  }
  nbits_ = visible_ = b;
  return true;
}

std::uint32_t Payload::extract(std::size_t start, std::size_t len) const {
  const std::size_t i = start >> 3;
  std::uint64_t w = 0;
  for (int k = 0; k < 5; ++k)
    w = (w << 8) | bytes_[i + k];
  const unsigned shift = static_cast<unsigned>(40 - (start & 7) - len);
  return static_cast<std::uint32_t>((w >> shift) & ((std::uint64_t{1} << len) - 1));
}

std::uint32_t Payload::u(std::size_t start, std::size_t len) const {
  if (start >= nbits_ || len == 0)
    return 0;
  if (start + len > nbits_)
    len = nbits_ - start;
  return extract(start, len);
}

std::int32_t Payload::s(std::size_t start, std::size_t len) const {
  if (start >= nbits_ || len == 0)
    return 0;
  if (start + len > nbits_)
    len = nbits_ - start;
  const std::uint32_t v = u(start, len);
  const std::uint32_t sign = std::uint32_t{1} << (len - 1);
  return static_cast<std::int32_t>((v ^ sign)) - static_cast<std::int32_t>(sign);
}

// ---- SI views ----

std::uint32_t Payload::ur(std::size_t start, std::size_t len) const {
  if (len == 0 || len > 32 || start >= visible_)
    return 0;
  const std::size_t present = std::min(len, visible_ - start);
  return extract(start, present) << (len - present);
}

std::int32_t Payload::sr(std::size_t start, std::size_t len) const {
  const std::uint32_t v = ur(start, len);
  if (len == 0 || len >= 32)
    return static_cast<std::int32_t>(v);
  const std::uint32_t sign = std::uint32_t{1} << (len - 1);
  return static_cast<std::int32_t>(v ^ sign) - static_cast<std::int32_t>(sign);
}

std::uint32_t Payload::rawByte(std::size_t start, std::size_t limit) const {
  std::uint32_t v = ur(start, 8);
  if (limit != 0 && start + 8 > limit)
    v &= limit > start ? (0xFFu << (8 - (limit - start))) & 0xFFu : 0u;
  return v;
}

std::optional<double> latDeg(std::int32_t raw) {
  if (raw == kLatNotAvailable || raw > 90 * 600000 || raw < -90 * 600000)
    return std::nullopt;
  return raw / 600000.0;
}

std::optional<double> lonDeg(std::int32_t raw) {
  if (raw == kLonNotAvailable || raw > 180 * 600000 || raw < -180 * 600000)
    return std::nullopt;
  return raw / 600000.0;
}

std::optional<double> speedMps(std::uint32_t raw) {
  if (raw >= kSpeedNotAvailable)
    return std::nullopt;
  return knotsToMps(raw / 10.0);  // 1022 means ">= 102.2 kn": the lower bound is the best value
}

std::optional<double> courseRad(std::uint32_t raw) {
  if (raw >= kCourseNotAvailable)
    return std::nullopt;
  return degToRad(raw / 10.0);
}

std::optional<double> headingRad(std::uint32_t raw) {
  if (raw >= 360)
    return std::nullopt;  // 511 = not available, 360..510 invalid
  return degToRad(static_cast<double>(raw));
}

std::optional<double> rateOfTurn(std::int32_t raw) {
  if (raw <= -127 || raw >= 127)
    return std::nullopt;
  const double r = raw / 4.733;
  const double deg_per_min = r * r * (raw < 0 ? -1.0 : 1.0);
  return degToRad(deg_per_min) / 60.0;
}

namespace {

void setPosition(Kinematics& k, std::int32_t lat, std::int32_t lon) {
  auto la = latDeg(lat), lo = lonDeg(lon);
  if (la && lo) {
    k.has_position = true;
    k.lat_deg = *la;
    k.lon_deg = *lo;
  }
}

void setMotion(Kinematics& k, std::uint32_t speed, std::uint32_t course, std::uint32_t heading) {
  if (auto v = speedMps(speed)) {
    k.has_speed = true;
    k.speed = *v;
  }
  if (auto c = courseRad(course)) {
    k.has_course = true;
    k.course = *c;
  }
  if (auto h = headingRad(heading)) {
    k.has_heading = true;
    k.heading = *h;
  }
}

}  // namespace

bool toKinematics(const Message& m, Kinematics& k) {
  k = Kinematics();
  k.mmsi = m.mmsi;
  if (auto* a = std::get_if<PositionReportA>(&m.body)) {
    setPosition(k, a->lat, a->lon);
    setMotion(k, a->speed, a->course, a->heading);
    if (auto r = rateOfTurn(a->turn)) {
      k.has_turn = true;
      k.rate_of_turn = *r;
    }
    if (a->turn != kTurnNotAvailable)
      k.turn_direction = a->turn > 0 ? 1 : (a->turn < 0 ? -1 : 0);
    return true;
  }
  if (auto* b = std::get_if<PositionReportB>(&m.body)) {
    setPosition(k, b->lat, b->lon);
    setMotion(k, b->speed, b->course, b->heading);
    return true;
  }
  if (auto* s = std::get_if<BaseStationReport>(&m.body)) {
    setPosition(k, s->lat, s->lon);
    return true;
  }
  if (auto* r = std::get_if<SarAircraftReport>(&m.body)) {
    setPosition(k, r->lat, r->lon);
    // Whole knots (1022 = 1022 kn or more, no exact value); course as in type 1.
    if (r->speed < 1022) {
      k.has_speed = true;
      k.speed = knotsToMps(static_cast<double>(r->speed));
    }
    if (auto c = courseRad(r->course)) {
      k.has_course = true;
      k.course = *c;
    }
    return true;
  }
  if (auto* n = std::get_if<AidToNavigation>(&m.body)) {
    setPosition(k, n->lat, n->lon);
    return true;
  }
  if (auto* l = std::get_if<LongRangeReport>(&m.body)) {
    // 1/10 min units: scale to 1/10000 min to share the range checks.
    if (l->lat != 91 * 600 && l->lon != 181 * 600)
      setPosition(k, l->lat * 1000, l->lon * 1000);
    if (l->speed < 63) {
      k.has_speed = true;
      k.speed = knotsToMps(static_cast<double>(l->speed));
    }
    if (l->course < 360) {
      k.has_course = true;
      k.course = degToRad(static_cast<double>(l->course));
    }
    return true;
  }
  return false;
}

// ---- Message decoding ----

namespace {

// MMSIs 98XXXYYYY are craft associated with a parent ship: their type 24B carries the mother ship's
// MMSI instead of the dimensions.
bool auxiliaryMmsi(std::uint32_t mmsi) {
  return mmsi / 10000000u == 98u;
}

Status decodeType1(const Payload& p, Message& m) {
  if (p.bits() < 163)
    return Status::kTooShort;
  PositionReportA r;
  r.status = static_cast<std::uint8_t>(p.u(38, 4));
  r.turn = p.s(42, 8);
  r.speed = p.u(50, 10);
  r.accuracy = p.u(60, 1) != 0;
  r.lon = p.s(61, 28);
  r.lat = p.s(89, 27);
  r.course = p.u(116, 12);
  r.heading = p.u(128, 9);
  r.second = static_cast<std::uint8_t>(p.u(137, 6));
  r.maneuver = static_cast<std::uint8_t>(p.u(143, 2));
  r.raim = p.u(148, 1) != 0;
  r.radio = p.u(149, 19);
  m.body = r;
  return Status::kMessage;
}

Status decodeType4(const Payload& p, Message& m) {
  if (p.bits() < 168)
    return Status::kTooShort;
  BaseStationReport r;
  r.year = p.u(38, 14);
  r.month = p.u(52, 4);
  r.day = p.u(56, 5);
  r.hour = p.u(61, 5);
  r.minute = p.u(66, 6);
  r.second = p.u(72, 6);
  r.accuracy = p.u(78, 1) != 0;
  r.lon = p.s(79, 28);
  r.lat = p.s(107, 27);
  r.epfd = static_cast<std::uint8_t>(p.u(134, 4));
  r.raim = p.u(148, 1) != 0;
  r.radio = p.u(149, 19);
  m.body = r;
  return Status::kMessage;
}

Status decodeType5(const Payload& p, Message& m) {
  // 424 by the standard; many transponders send 420 or 422 (gpsd accepts them too).
  if (p.bits() < 420)
    return Status::kTooShort;
  m.body = StaticVoyageData();
  auto& r = std::get<StaticVoyageData>(m.body);
  r.ais_version = static_cast<std::uint8_t>(p.u(38, 2));
  r.imo = p.u(40, 30);
  p.text(70, 7, r.callsign);
  p.text(112, 20, r.shipname);
  r.shiptype = static_cast<std::uint8_t>(p.u(232, 8));
  r.to_bow = p.u(240, 9);
  r.to_stern = p.u(249, 9);
  r.to_port = p.u(258, 6);
  r.to_starboard = p.u(264, 6);
  r.epfd = static_cast<std::uint8_t>(p.u(270, 4));
  r.month = p.u(274, 4);
  r.day = p.u(278, 5);
  r.hour = p.u(283, 5);
  r.minute = p.u(288, 6);
  r.draught = p.u(294, 8);
  p.text(302, 20, r.destination);
  r.dte = p.bits() >= 423 && p.u(422, 1) != 0;
  return Status::kMessage;
}

Status decodeType18or19(const Payload& p, Message& m) {
  const bool extended = m.type == 19;
  if (p.bits() < (extended ? 312u : 168u))
    return Status::kTooShort;
  m.body = PositionReportB();
  auto& r = std::get<PositionReportB>(m.body);
  r.reserved = p.u(38, 8);
  r.speed = p.u(46, 10);
  r.accuracy = p.u(56, 1) != 0;
  r.lon = p.s(57, 28);
  r.lat = p.s(85, 27);
  r.course = p.u(112, 12);
  r.heading = p.u(124, 9);
  r.second = static_cast<std::uint8_t>(p.u(133, 6));
  if (!extended) {
    r.regional = p.u(139, 2);
    r.cs = p.u(141, 1) != 0;
    r.display = p.u(142, 1) != 0;
    r.dsc = p.u(143, 1) != 0;
    r.band = p.u(144, 1) != 0;
    r.msg22 = p.u(145, 1) != 0;
    r.assigned = p.u(146, 1) != 0;
    r.raim = p.u(147, 1) != 0;
    r.radio = p.u(148, 20);
  } else {
    r.regional = p.u(139, 4);
    p.text(143, 20, r.shipname);
    r.shiptype = static_cast<std::uint8_t>(p.u(263, 8));
    r.to_bow = p.u(271, 9);
    r.to_stern = p.u(280, 9);
    r.to_port = p.u(289, 6);
    r.to_starboard = p.u(295, 6);
    r.epfd = static_cast<std::uint8_t>(p.u(301, 4));
    r.raim = p.u(305, 1) != 0;
    r.dte = p.u(306, 1) != 0;
    r.assigned = p.u(307, 1) != 0;
  }
  return Status::kMessage;
}

Status decodeType21(const Payload& p, Message& m) {
  // 272 bits plus a name extension of up to 14 characters; gpsd 3.22 takes up to 368.
  if (p.bits() < 272)
    return Status::kTooShort;
  if (p.bits() > 368)
    return Status::kTooLong;
  m.body = AidToNavigation();
  auto& r = std::get<AidToNavigation>(m.body);
  r.aid_type = static_cast<std::uint8_t>(p.u(38, 5));
  p.text(43, 20, r.name, false);
  r.accuracy = p.u(163, 1) != 0;
  r.lon = p.s(164, 28);
  r.lat = p.s(192, 27);
  r.to_bow = p.u(219, 9);
  r.to_stern = p.u(228, 9);
  r.to_port = p.u(237, 6);
  r.to_starboard = p.u(243, 6);
  r.epfd = static_cast<std::uint8_t>(p.u(249, 4));
  r.second = static_cast<std::uint8_t>(p.u(253, 6));
  r.off_position = p.u(259, 1) != 0;
  r.regional = p.u(260, 8);
  r.raim = p.u(268, 1) != 0;
  r.virtual_aid = p.u(269, 1) != 0;
  r.assigned = p.u(270, 1) != 0;
  // The name extension (up to 14 more characters after bit 272) only continues a full name.
  if (r.name.size() == 20 && p.bits() > 272)
    p.appendText(272, (p.bits() - 272) / 6, r.name, false);
  Payload::trimRight(r.name);
  return Status::kMessage;
}

Status decodeType24(const Payload& p, Message& m) {
  const std::uint32_t part = p.u(38, 2);
  if (part > 1)
    return Status::kBadPart;
  if (p.bits() < (part == 0 ? 160u : 168u))
    return Status::kTooShort;
  if (part == 0 && p.bits() > 168)  // 160 bits, or the whole slot; gpsd 3.22 takes no more
    return Status::kTooLong;
  m.body = StaticDataReport();
  auto& r = std::get<StaticDataReport>(m.body);
  r.part = static_cast<std::uint8_t>(part);
  if (part == 0) {
    p.text(40, 20, r.shipname);
    return Status::kMessage;
  }
  r.shiptype = static_cast<std::uint8_t>(p.u(40, 8));
  // ITU-R M.1371-4 carved model and serial out of the vendor id; like gpsd, read both ways.
  p.text(48, 7, r.vendorid);
  r.model = p.u(66, 4);
  r.serial = p.u(70, 20);
  p.text(90, 7, r.callsign);
  if (auxiliaryMmsi(m.mmsi)) {
    r.mothership_mmsi = p.u(132, 30);
  } else {
    r.to_bow = p.u(132, 9);
    r.to_stern = p.u(141, 9);
    r.to_port = p.u(150, 6);
    r.to_starboard = p.u(156, 6);
  }
  return Status::kMessage;
}

Status decodeType27(const Payload& p, Message& m) {
  // 96 bits; some senders fill the whole 168-bit slot (gpsd 3.22 takes exactly these two lengths).
  if (p.bits() < 96)
    return Status::kTooShort;
  if (p.bits() != 96 && p.bits() != 168)
    return Status::kTooLong;
  LongRangeReport r;
  r.accuracy = p.u(38, 1) != 0;
  r.raim = p.u(39, 1) != 0;
  r.status = static_cast<std::uint8_t>(p.u(40, 4));
  r.lon = p.s(44, 18);
  r.lat = p.s(62, 17);
  r.speed = p.u(79, 6);
  r.course = p.u(85, 9);
  r.gnss = p.u(94, 1) != 0;
  m.body = r;
  return Status::kMessage;
}

Status decodeType9(const Payload& p, Message& m) {
  SarAircraftReport r;
  r.alt = p.u(38, 12);
  r.speed = p.u(50, 10);
  r.accuracy = p.u(60, 1) != 0;
  r.lon = p.s(61, 28);
  r.lat = p.s(89, 27);
  r.course = p.u(116, 12);
  r.second = static_cast<std::uint8_t>(p.u(128, 6));
  r.regional = p.u(134, 8);
  r.dte = p.u(142, 1) != 0;
  r.assigned = p.u(146, 1) != 0;
  r.raim = p.u(147, 1) != 0;
  r.radio = p.u(148, 20);
  m.body = r;
  return Status::kMessage;
}

Status decodeSafetyText(const Payload& p, Message& m) {
  m.body = SafetyText();
  auto& r = std::get<SafetyText>(m.body);
  std::size_t start = 40;
  if (m.type == 12) {
    r.seqno = static_cast<std::uint8_t>(p.u(38, 2));
    r.dest_mmsi = p.u(40, 30);
    r.retransmit = p.u(70, 1) != 0;
    start = 72;
  }
  p.text(start, (p.bits() - start) / 6, r.text);
  return Status::kMessage;
}

Status decodePayloadMessage(const Payload& p, Message& m) {
  PayloadMessage r;
  if (m.type == 6) {
    r.dac = p.u(72, 10);
    r.fid = p.u(82, 6);
  } else if (m.type == 8) {
    r.dac = p.u(40, 10);
    r.fid = p.u(50, 6);
  }
  m.body = r;
  return Status::kMessage;
}

// Lengths gpsd 3.22 accepts, in bits, for the types decoded after the first ten (index: type).
struct LengthRule {
  std::uint16_t min, max;
};
constexpr LengthRule kLengths[28] = {{0, 0},     {0, 0},    {0, 0},     {0, 0},      {0, 0},      {0, 0},
                                     {88, 1008}, {72, 168}, {56, 1008}, {168, 1008}, {72, 1008},  {168, 1008},
                                     {72, 1008}, {72, 168}, {40, 1008}, {88, 168},   {96, 168},   {80, 816},
                                     {0, 0},     {0, 0},    {72, 186},  {0, 0},      {168, 1008}, {160, 1008},
                                     {0, 0},     {40, 168}, {60, 1004}, {0, 0}};

// Types 25 and 26 must also hold the destination and application id their flags announce.
bool slotBinaryFits(const Payload& p, unsigned type) {
  const std::size_t need = 40 + (p.u(39, 1) ? 16 : 0) + (p.u(38, 1) ? 30 : 0) + (type == 26 ? 20 : 0);
  return p.bits() >= need;
}

Status decodeOtherType(const Payload& p, Message& m) {
  const LengthRule rule = kLengths[m.type];
  if (p.bits() < rule.min || ((m.type == 25 || m.type == 26) && !slotBinaryFits(p, m.type)))
    return Status::kTooShort;
  if (p.bits() > rule.max)
    return Status::kTooLong;
  switch (m.type) {
    case 9:
      return decodeType9(p, m);
    case 11:
      return decodeType4(p, m);
    case 12:
    case 14:
      return decodeSafetyText(p, m);
    default:
      return decodePayloadMessage(p, m);
  }
}

}  // namespace

Status decodePayload(const Payload& p, Message& m) {
  if (p.bits() < 38)
    return p.bits() == 0 ? Status::kEmptyPayload : Status::kTooShort;
  m.type = static_cast<std::uint8_t>(p.u(0, 6));
  m.repeat = static_cast<std::uint8_t>(p.u(6, 2));
  m.mmsi = p.u(8, 30);
  switch (m.type) {
    case 1:
    case 2:
    case 3:
      return decodeType1(p, m);
    case 4:
      return decodeType4(p, m);
    case 5:
      return decodeType5(p, m);
    case 18:
    case 19:
      return decodeType18or19(p, m);
    case 21:
      return decodeType21(p, m);
    case 24:
      return decodeType24(p, m);
    case 27:
      return decodeType27(p, m);
    case 6:
    case 7:
    case 8:
    case 9:
    case 10:
    case 11:
    case 12:
    case 13:
    case 14:
    case 15:
    case 16:
    case 17:
    case 20:
    case 22:
    case 23:
    case 25:
    case 26:
      return decodeOtherType(p, m);
    default:
      return Status::kUnsupportedType;  // 0 and 28-63 are not defined
  }
}

// ---- Decoder ----

void DecoderConfig::validate() const {
  if (!(fragment_timeout > 0.0) || !std::isfinite(fragment_timeout))
    throw std::invalid_argument("ais::DecoderConfig::fragment_timeout must be > 0 s");
  if (max_pending < 1 || max_pending > 4096)
    throw std::invalid_argument("ais::DecoderConfig::max_pending must be in [1, 4096]");
}

const char* statusText(Status s) {
  switch (s) {
    case Status::kMessage:
      return "message";
    case Status::kPending:
      return "fragment pending";
    case Status::kNotAis:
      return "not an AIVDM/AIVDO sentence";
    case Status::kBadFields:
      return "bad AIVDM fields";
    case Status::kBadFill:
      return "bad fill bits";
    case Status::kBadArmour:
      return "bad six-bit armour or payload too long";
    case Status::kEmptyPayload:
      return "empty payload";
    case Status::kOrphanFragment:
      return "orphan fragment";
    case Status::kOutOfOrder:
      return "out-of-order fragment";
    case Status::kUnsupportedType:
      return "unsupported message type";
    case Status::kTooShort:
      return "payload too short for its type";
    case Status::kBadPart:
      return "type 24 part number not 0 or 1";
    case Status::kTooLong:
      return "payload too long for its type";
    case Status::kCount:
      break;
  }
  return "unknown";
}

Decoder::Decoder(const DecoderConfig& config) : config_(config), pending_(config.max_pending) {
  config_.validate();
}

Status Decoder::count(Status s) {
  switch (s) {
    case Status::kMessage:
      ++counters_.messages;
      break;
    case Status::kPending:
      ++counters_.pending;
      break;
    case Status::kBadFields:
      ++counters_.bad_fields;
      break;
    case Status::kBadFill:
      ++counters_.bad_fill;
      break;
    case Status::kBadArmour:
      ++counters_.bad_armour;
      break;
    case Status::kEmptyPayload:
      ++counters_.empty_payload;
      break;
    case Status::kOrphanFragment:
      ++counters_.orphans;
      break;
    case Status::kOutOfOrder:
      ++counters_.out_of_order;
      break;
    case Status::kUnsupportedType:
      ++counters_.unsupported;
      break;
    case Status::kTooShort:
      ++counters_.too_short;
      break;
    case Status::kBadPart:
      ++counters_.bad_part;
      break;
    case Status::kTooLong:
      ++counters_.too_long;
      break;
    default:
      break;
  }
  return s;
}

std::size_t Decoder::pendingCount() const {
  return npending_;
}

void Decoder::expire(double now) {
  if (npending_ == 0)
    return;
  for (auto& p : pending_) {
    if (p.used && now - p.started > config_.fragment_timeout) {
      p.used = false;
      --npending_;
      ++counters_.timeouts;
    }
  }
}

void Decoder::clearPending() {
  for (auto& p : pending_)
    p.used = false;
  npending_ = 0;
}

Status Decoder::complete(std::string_view armoured, int fill, Message& out) {
  payload_.clear();
  if (!payload_.append(armoured))
    return Status::kBadArmour;
  payload_.dropFill(fill);
  if (payload_.bits() == 0)
    return Status::kEmptyPayload;
  return decodePayload(payload_, out);
}

namespace {

inline bool singleDigit(std::string_view f, int& v) {
  if (f.size() != 1 || f[0] < '0' || f[0] > '9')
    return false;
  v = f[0] - '0';
  return true;
}

inline bool validArmour(std::string_view s) {
  for (char ch : s) {
    unsigned c = static_cast<unsigned char>(ch);
    if (c < 48 || c > 119 || (c > 87 && c < 96))
      return false;
  }
  return true;
}

// FNV-1a: a cheap, stable hash of the tag-block source for the reassembly key.
std::uint32_t hashSource(std::string_view s) {
  std::uint32_t h = 2166136261u;
  for (char c : s)
    h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return h;
}

}  // namespace

Status Decoder::feed(const nmea::Sentence& s, double now, Message& out) {
  const bool vdm = s.type == "VDM";
  if (!vdm && s.type != "VDO")
    return Status::kNotAis;
  ++counters_.sentences;
  if (s.field_count < 7)
    return count(Status::kBadFields);

  int total, number;
  if (!singleDigit(s.field(1), total) || total < 1 || !singleDigit(s.field(2), number) || number < 1 ||
      number > total)
    return count(Status::kBadFields);
  const std::string_view seq_field = s.field(3);
  int seq = 10;  // "no sequence id" is its own key value
  if (!seq_field.empty() && !singleDigit(seq_field, seq))
    return count(Status::kBadFields);
  const std::string_view channel_field = s.field(4);
  if (channel_field.size() > 2)
    return count(Status::kBadFields);
  const char channel = channel_field.empty() ? '\0' : channel_field[0];
  const std::string_view armoured = s.field(5);
  int fill = 0;
  const std::string_view fill_field = s.field(6);
  if (fill_field.empty() && number < total) {
    fill = 0;  // some receivers leave the fill of non-final fragments empty
  } else if (!singleDigit(fill_field, fill) || fill > 5) {
    return count(Status::kBadFill);
  }

  out.channel = channel;
  out.own_ship = !vdm;
  out.has_time = s.tag.has_time;
  out.unix_time = s.tag.unix_time;

  if (total == 1) {
    if (armoured.empty())
      return count(Status::kEmptyPayload);
    return count(complete(armoured, fill, out));
  }

  expire(now);
  if (!validArmour(armoured))
    return count(Status::kBadArmour);
  const std::uint64_t key = static_cast<std::uint64_t>(static_cast<unsigned char>(channel)) |
                            (static_cast<std::uint64_t>(seq) << 8) |
                            (static_cast<std::uint64_t>(total) << 16) |
                            (static_cast<std::uint64_t>(vdm ? 0 : 1) << 24) |
                            (config_.key_by_source && !s.tag.source.empty()
                                 ? static_cast<std::uint64_t>(hashSource(s.tag.source)) << 32
                                 : 0);
  Pending* slot = nullptr;
  for (auto& p : pending_) {
    if (p.used && p.key == key) {
      slot = &p;
      break;
    }
  }

  if (number == 1) {
    if (slot) {
      ++counters_.restarted;  // the previous message with this key never completed
    } else {
      Pending* oldest = nullptr;
      for (auto& p : pending_) {
        if (!p.used) {
          slot = &p;
          break;
        }
        if (!oldest || p.order < oldest->order)
          oldest = &p;
      }
      if (!slot) {
        slot = oldest;
        ++counters_.evicted;
      } else {
        ++npending_;
      }
    }
    if (armoured.size() > kMaxPayloadChars) {
      slot->used = false;
      --npending_;
      return count(Status::kBadArmour);
    }
    slot->used = true;
    slot->key = key;
    slot->count = total;
    slot->next = 2;
    slot->started = now;
    slot->order = ++order_;
    std::memcpy(slot->chars.data(), armoured.data(), armoured.size());
    slot->nchars = armoured.size();
    return count(Status::kPending);
  }

  if (!slot)
    return count(Status::kOrphanFragment);
  if (number != slot->next) {
    slot->used = false;
    --npending_;
    return count(Status::kOutOfOrder);
  }
  if (slot->nchars + armoured.size() > kMaxPayloadChars) {
    slot->used = false;
    --npending_;
    return count(Status::kBadArmour);
  }
  std::memcpy(slot->chars.data() + slot->nchars, armoured.data(), armoured.size());
  slot->nchars += armoured.size();
  if (number < total) {
    ++slot->next;
    return count(Status::kPending);
  }
  slot->used = false;
  --npending_;
  return count(complete(std::string_view(slot->chars.data(), slot->nchars), fill, out));
}

Status Decoder::feedLine(std::string_view line, double now, Message& out, nmea::Reject* reject) {
  const nmea::Reject r = nmea::parseSentence(line, sentence_, framer_);
  if (reject)
    *reject = r;
  if (r != nmea::Reject::kNone)
    return Status::kNotAis;
  return feed(sentence_, now, out);
}

// ---- StaticStore ----

void StaticStoreConfig::validate() const {
  if (max_ships < 1)
    throw std::invalid_argument("ais::StaticStoreConfig::max_ships must be >= 1");
}

StaticStore::StaticStore(const StaticStoreConfig& config) : config_(config) {
  config_.validate();
}

void StaticStore::evictIfFull() {
  if (ships_.size() < config_.max_ships)
    return;
  auto oldest = ships_.begin();
  for (auto it = ships_.begin(); it != ships_.end(); ++it)
    if (it->second.stamp < oldest->second.stamp)
      oldest = it;
  ships_.erase(oldest);
}

const ShipStatic* StaticStore::update(const Message& m) {
  const auto* v = std::get_if<StaticVoyageData>(&m.body);
  const auto* b = std::get_if<PositionReportB>(&m.body);
  const auto* s = std::get_if<StaticDataReport>(&m.body);
  if (!v && !(b && m.type == 19) && !s)
    return nullptr;
  auto it = ships_.find(m.mmsi);
  if (it == ships_.end()) {
    evictIfFull();
    it = ships_.emplace(m.mmsi, Entry()).first;
    it->second.data.mmsi = m.mmsi;
  }
  Entry& e = it->second;
  e.stamp = ++stamp_;
  ShipStatic& d = e.data;
  auto setDims = [&d](std::uint32_t bow, std::uint32_t stern, std::uint32_t port, std::uint32_t stbd) {
    d.to_bow = bow;
    d.to_stern = stern;
    d.to_port = port;
    d.to_starboard = stbd;
    d.has_dimensions = bow + stern > 0;
  };
  auto setName = [&d](const Text20& name) {
    if (name.empty())
      return;
    d.shipname = name;
    d.has_name = true;
  };
  if (v) {
    setName(v->shipname);
    d.callsign = v->callsign;
    d.imo = v->imo;
    d.shiptype = v->shiptype;
    d.has_type = v->shiptype != 0;
    setDims(v->to_bow, v->to_stern, v->to_port, v->to_starboard);
    d.destination = v->destination;
    d.draught = v->draught;
  } else if (b) {
    setName(b->shipname);
    d.shiptype = b->shiptype;
    d.has_type = b->shiptype != 0;
    setDims(b->to_bow, b->to_stern, b->to_port, b->to_starboard);
  } else if (s->part == 0) {
    setName(s->shipname);
  } else {
    d.callsign = s->callsign;
    d.shiptype = s->shiptype;
    d.has_type = s->shiptype != 0;
    if (!auxiliaryMmsi(m.mmsi))
      setDims(s->to_bow, s->to_stern, s->to_port, s->to_starboard);
  }
  return &d;
}

const ShipStatic* StaticStore::find(std::uint32_t mmsi) const {
  auto it = ships_.find(mmsi);
  return it == ships_.end() ? nullptr : &it->second.data;
}

// ---- Legends (gpsd's wording, so the CLI output matches gpsdecode) ----

const char* navStatusText(unsigned status) {
  static const char* const kText[16] = {"Under way using engine",
                                        "At anchor",
                                        "Not under command",
                                        "Restricted manoeuverability",
                                        "Constrained by her draught",
                                        "Moored",
                                        "Aground",
                                        "Engaged in fishing",
                                        "Under way sailing",
                                        "Reserved for HSC",
                                        "Reserved for WIG",
                                        "Reserved",
                                        "Reserved",
                                        "Reserved",
                                        "Reserved",
                                        "Not defined"};
  return kText[status & 15u];
}

const char* epfdText(unsigned epfd) {
  static const char* const kText[9] = {"Undefined",
                                       "GPS",
                                       "GLONASS",
                                       "Combined GPS/GLONASS",
                                       "Loran-C",
                                       "Chayka",
                                       "Integrated navigation system",
                                       "Surveyed",
                                       "Galileo"};
  return epfd < 9 ? kText[epfd] : "INVALID EPFD";
}

const char* shipTypeText(unsigned t) {
  static const char* const kSpecial[10] = {"Fishing",
                                           "Towing",
                                           "Towing: length exceeds 200m or breadth exceeds 25m",
                                           "Dredging or underwater ops",
                                           "Diving ops",
                                           "Military ops",
                                           "Sailing",
                                           "Pleasure Craft",
                                           "Reserved",
                                           "Reserved"};
  static const char* const kOther[10] = {"Pilot Vessel",
                                         "Search and Rescue vessel",
                                         "Tug",
                                         "Port Tender",
                                         "Anti-pollution equipment",
                                         "Law Enforcement",
                                         "Spare - Local Vessel",
                                         "Spare - Local Vessel",
                                         "Medical Transport",
                                         "Ship according to RR Resolution No. 18"};
  static const char* const kCategory[5][10] = {
      {"Wing in ground (WIG) - all ships of this type", "Wing in ground (WIG) - Hazardous category A",
       "Wing in ground (WIG) - Hazardous category B", "Wing in ground (WIG) - Hazardous category C",
       "Wing in ground (WIG) - Hazardous category D", "Wing in ground (WIG) - Reserved for future use",
       "Wing in ground (WIG) - Reserved for future use", "Wing in ground (WIG) - Reserved for future use",
       "Wing in ground (WIG) - Reserved for future use", "Wing in ground (WIG) - Reserved for future use"},
      {"High speed craft (HSC) - all ships of this type", "High speed craft (HSC) - Hazardous category A",
       "High speed craft (HSC) - Hazardous category B", "High speed craft (HSC) - Hazardous category C",
       "High speed craft (HSC) - Hazardous category D", "High speed craft (HSC) - Reserved for future use",
       "High speed craft (HSC) - Reserved for future use", "High speed craft (HSC) - Reserved for future use",
       "High speed craft (HSC) - Reserved for future use",
       "High speed craft (HSC) - No additional information"},
      {"Passenger - all ships of this type", "Passenger - Hazardous category A",
       "Passenger - Hazardous category B", "Passenger - Hazardous category C",
       "Passenger - Hazardous category D", "Passenger - Reserved for future use",
       "Passenger - Reserved for future use", "Passenger - Reserved for future use",
       "Passenger - Reserved for future use", "Passenger - No additional information"},
      {"Cargo - all ships of this type", "Cargo - Hazardous category A", "Cargo - Hazardous category B",
       "Cargo - Hazardous category C", "Cargo - Hazardous category D", "Cargo - Reserved for future use",
       "Cargo - Reserved for future use", "Cargo - Reserved for future use",
       "Cargo - Reserved for future use", "Cargo - No additional information"},
      {"Tanker - all ships of this type", "Tanker - Hazardous category A", "Tanker - Hazardous category B",
       "Tanker - Hazardous category C", "Tanker - Hazardous category D", "Tanker - Reserved for future use",
       "Tanker - Reserved for future use", "Tanker - Reserved for future use",
       "Tanker - Reserved for future use", "Tanker - No additional information"}};
  static const char* const kOtherType[10] = {
      "Other Type - all ships of this type",  "Other Type - Hazardous category A",
      "Other Type - Hazardous category B",    "Other Type - Hazardous category C",
      "Other Type - Hazardous category D",    "Other Type - Reserved for future use",
      "Other Type - Reserved for future use", "Other Type - Reserved for future use",
      "Other Type - Reserved for future use", "Other Type - no additional information"};
  if (t == 0)
    return "Not available";
  if (t < 20)
    return "Reserved for future use";
  if (t >= 100)
    return "INVALID SHIP TYPE";
  const unsigned d = t / 10, u = t % 10;
  switch (d) {
    case 2:
      return kCategory[0][u];
    case 3:
      return kSpecial[u];
    case 4:
      return kCategory[1][u];
    case 5:
      return kOther[u];
    case 6:
      return kCategory[2][u];
    case 7:
      return kCategory[3][u];
    case 8:
      return kCategory[4][u];
    default:
      return kOtherType[u];
  }
}

const char* aidTypeText(unsigned a) {
  static const char* const kText[32] = {"Unspecified",
                                        "Reference point",
                                        "RACON",
                                        "Fixed offshore structure",
                                        "Spare, Reserved for future use.",
                                        "Light, without sectors",
                                        "Light, with sectors",
                                        "Leading Light Front",
                                        "Leading Light Rear",
                                        "Beacon, Cardinal N",
                                        "Beacon, Cardinal E",
                                        "Beacon, Cardinal S",
                                        "Beacon, Cardinal W",
                                        "Beacon, Port hand",
                                        "Beacon, Starboard hand",
                                        "Beacon, Preferred Channel port hand",
                                        "Beacon, Preferred Channel starboard hand",
                                        "Beacon, Isolated danger",
                                        "Beacon, Safe water",
                                        "Beacon, Special mark",
                                        "Cardinal Mark N",
                                        "Cardinal Mark E",
                                        "Cardinal Mark S",
                                        "Cardinal Mark W",
                                        "Port hand Mark",
                                        "Starboard hand Mark",
                                        "Preferred Channel Port hand",
                                        "Preferred Channel Starboard hand",
                                        "Isolated danger",
                                        "Safe Water",
                                        "Special Mark",
                                        "Light Vessel / LANBY / Rigs"};
  return kText[a & 31u];
}

const char* stationTypeText(unsigned t) {
  static const char* const kText[16] = {"All types of mobiles",
                                        "Reserved for future use",
                                        "All types of Class B mobile stations",
                                        "SAR airborne mobile station",
                                        "Aid to Navigation station",
                                        "Class B shipborne mobile station",
                                        "Regional use and inland waterways",
                                        "Regional use and inland waterways",
                                        "Regional use and inland waterways",
                                        "Regional use and inland waterways",
                                        "Reserved for future use",
                                        "Reserved for future use",
                                        "Reserved for future use",
                                        "Reserved for future use",
                                        "Reserved for future use",
                                        "Reserved for future use"};
  return kText[t & 15u];
}

}  // namespace ais
}  // namespace asv
