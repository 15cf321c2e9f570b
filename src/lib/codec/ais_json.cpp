#include "asv_core/codec/ais_json.h"

#include <cstdio>

namespace asv {
namespace ais {

void AisFields::f(const char* name, double v, int decimals) {
  static const char* const kFormats[] = {"%.0f", "%.1f", "%.2f", "%.3f", "%.4f", "%.5f", "%.6f"};
  key(name);
  o_.printf1(kFormats[decimals < 0 ? 0 : (decimals > 6 ? 6 : decimals)], v);
}

void AisFields::text6(const char* name, const Payload& p, std::size_t start, std::size_t nchars) {
  FixedString<Payload::kMaxTextChars> t;
  for (std::size_t k = 0; k < nchars; ++k) {
    const char c = Payload::sixbitChar(p.ur(start + 6 * k, 6));
    if (c == '@')
      break;
    t.push_back(c);
  }
  Payload::trimRight(t);
  str(name, t.view());
}

void AisFields::data(const char* name, const Payload& p, std::size_t start) {
  dataBits(name, p, start, p.bits() > start ? p.bits() - start : 0, 0);
}

void AisFields::dataBits(const char* name, const Payload& p, std::size_t start, std::size_t count,
                         std::size_t limit) {
  static const char kHex[] = "0123456789abcdef";
  key(name);
  o_.ch('"');
  o_.u(count);
  o_.ch(':');
  for (std::size_t k = 0; k < count; k += 8) {
    const std::uint32_t byte = p.rawByte(start + k, limit);
    o_.ch(kHex[byte >> 4]);
    o_.ch(kHex[byte & 15]);
  }
  o_.ch('"');
}

void AisFields::stamp(const char* name, unsigned month, unsigned day, unsigned hour, unsigned minute,
                      bool with_month) {
  key(name);
  o_.ch('"');
  stampBody(month, day, hour, minute, with_month);
  o_.lit("Z\"");
}

void AisFields::stampBody(unsigned month, unsigned day, unsigned hour, unsigned minute, bool with_month) {
  if (with_month) {
    o_.pad(month, 2);
    o_.ch('-');
  }
  o_.pad(day, 2);
  o_.ch('T');
  o_.pad(hour, 2);
  o_.ch(':');
  o_.pad(minute, 2);
}

void writeRouteInformation(const Payload& p, std::size_t base, const char* rtype_text, AisFields& w) {
  constexpr double kTenThousandthMinutesPerDeg = 600000.0;
  w.u("linkage", p.ur(base, 10));
  w.u("sender", p.ur(base + 10, 3));
  w.withText("rtype", p.ur(base + 13, 5), "rtype_text", rtype_text);
  w.stamp("start", p.ur(base + 18, 4), p.ur(base + 22, 5), p.ur(base + 27, 5), p.ur(base + 32, 6));
  w.u("duration", p.ur(base + 38, 18));
  const unsigned count = p.ur(base + 56, 5);
  w.beginArray("waypoints");
  for (std::size_t k = 0, a = base + 61; k < count; ++k, a += 55) {
    w.beginObject();
    w.scaledDiv("lon", p.sr(a, 28), kTenThousandthMinutesPerDeg, 6);
    w.scaledDiv("lat", p.sr(a + 28, 27), kTenThousandthMinutesPerDeg, 6);
    w.endObject();
  }
  w.endArray();
}

namespace {

// Positions of types 17, 22 and 23 are in 1/10 minute.
constexpr double kTenthMinutesPerDeg = 600.0;

void writeType6(const Payload& p, AisFields& w) {
  w.u("seqno", p.u(38, 2));
  w.u("dest_mmsi", p.u(40, 30));
  w.b("retransmit", p.u(70, 1) != 0);
  const unsigned dac = p.u(72, 10);
  const unsigned fid = p.u(82, 6);
  w.u("dac", dac);
  w.u("fid", fid);
  if (!writeType6Application(p, dac, fid, w))
    w.data("data", p, 88);
}

void writeType8(const Payload& p, AisFields& w) {
  const unsigned dac = p.u(40, 10);
  const unsigned fid = p.u(50, 6);
  w.u("dac", dac);
  w.u("fid", fid);
  // gpsd 3.22 clears the bits after the data in the last byte of type 8 only (the fill bits show in
  // types 6, 17, 25 and 26).
  if (!writeType8Application(p, dac, fid, w))
    w.dataBits("data", p, 56, p.bits() > 56 ? p.bits() - 56 : 0, p.bits());
}

// Types 7 and 13: up to four acknowledged MMSIs (with their sequence numbers, not printed).
void writeAcknowledge(const Payload& p, AisFields& w) {
  static const char* const kNames[] = {"mmsi1", "mmsi2", "mmsi3", "mmsi4"};
  for (unsigned k = 0; k < 4; ++k)
    w.u(kNames[k], p.bits() > 40 + 32 * k ? p.ur(40 + 32 * k, 30) : 0);
}

void writeType9(const Payload& p, AisFields& w) {
  const std::uint32_t alt = p.u(38, 12);  // m: 4095 not available, 4094 at or above 4094 m
  if (w.scaled() && alt == 4095)
    w.str("alt", "nan");
  else if (w.scaled() && alt == 4094)
    w.str("alt", "high");
  else
    w.u("alt", alt);
  const std::uint32_t speed = p.u(50, 10);  // whole knots: 1023 not available, 1022 fast
  if (w.scaled() && speed == 1023)
    w.str("speed", "nan");
  else if (w.scaled() && speed == 1022)
    w.str("speed", "fast");
  else
    w.u("speed", speed);
  w.b("accuracy", p.u(60, 1) != 0);
  json::Out& o = w.out();
  if (w.scaled()) {
    w.key("lon");
    o.latlon(p.s(61, 28));
    w.key("lat");
    o.latlon(p.s(89, 27));
    w.key("course");
    o.tenths(p.u(116, 12));
  } else {
    w.i("lon", p.s(61, 28));
    w.i("lat", p.s(89, 27));
    w.u("course", p.u(116, 12));
  }
  w.u("second", p.u(128, 6));
  w.u("regional", p.u(134, 8));
  w.u("dte", p.u(142, 1));
  w.b("raim", p.u(147, 1) != 0);
  w.u("radio", p.u(148, 20));
}

void writeType15(const Payload& p, AisFields& w) {
  const bool second = p.bits() > 90, third = p.bits() > 110;
  w.u("mmsi1", p.ur(40, 30));
  w.u("type1_1", p.ur(70, 6));
  w.u("offset1_1", p.ur(76, 12));
  w.u("type1_2", second ? p.ur(90, 6) : 0);
  w.u("offset1_2", second ? p.ur(96, 12) : 0);
  w.u("mmsi2", third ? p.ur(110, 30) : 0);
  w.u("type2_1", third ? p.ur(140, 6) : 0);
  w.u("offset2_1", third ? p.ur(146, 12) : 0);
}

void writeType16(const Payload& p, AisFields& w) {
  const bool second = p.bits() >= 144;
  w.u("mmsi1", p.ur(40, 30));
  w.u("offset1", p.ur(70, 12));
  w.u("increment1", p.ur(82, 10));
  w.u("mmsi2", second ? p.ur(92, 30) : 0);
  w.u("offset2", second ? p.ur(122, 12) : 0);
  w.u("increment2", second ? p.ur(134, 10) : 0);
}

void writeType17(const Payload& p, AisFields& w) {
  w.scaledDiv("lon", p.s(40, 18), kTenthMinutesPerDeg, 1);
  w.scaledDiv("lat", p.s(58, 17), kTenthMinutesPerDeg, 1);
  w.data("data", p, 80);
}

void writeType20(const Payload& p, AisFields& w) {
  static const char* const kNames[4][4] = {{"offset1", "number1", "timeout1", "increment1"},
                                           {"offset2", "number2", "timeout2", "increment2"},
                                           {"offset3", "number3", "timeout3", "increment3"},
                                           {"offset4", "number4", "timeout4", "increment4"}};
  for (unsigned k = 0; k < 4; ++k) {
    const std::size_t b = 40 + 30 * k;
    w.u(kNames[k][0], p.ur(b, 12));
    w.u(kNames[k][1], p.ur(b + 12, 4));
    w.u(kNames[k][2], p.ur(b + 16, 3));
    w.u(kNames[k][3], p.ur(b + 19, 11));
  }
}

// Corner of a type 22/23 area: gpsd quotes the scaled value ("%.6f" in a string).
void corner(AisFields& w, const char* name, std::int32_t raw) {
  if (!w.scaled()) {
    w.i(name, raw);
    return;
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6f", raw / kTenthMinutesPerDeg);
  w.str(name, buf);
}

void writeType22(const Payload& p, AisFields& w) {
  const bool addressed = p.u(139, 1) != 0;
  w.u("channel_a", p.u(40, 12));
  w.u("channel_b", p.u(52, 12));
  w.u("txrx", p.u(64, 4));
  w.b("power", p.u(68, 1) != 0);
  if (addressed) {
    w.u("dest1", p.u(69, 30));
    w.u("dest2", p.u(104, 30));
  } else {
    corner(w, "ne_lon", p.s(69, 18));
    corner(w, "ne_lat", p.s(87, 17));
    corner(w, "sw_lon", p.s(104, 18));
    corner(w, "sw_lat", p.s(122, 17));
  }
  w.b("addressed", addressed);
  w.b("band_a", p.u(140, 1) != 0);
  w.b("band_b", p.u(141, 1) != 0);
  w.u("zonesize", p.u(142, 3));
}

void writeType23(const Payload& p, AisFields& w) {
  corner(w, "ne_lon", p.s(40, 18));
  corner(w, "ne_lat", p.s(58, 17));
  corner(w, "sw_lon", p.s(75, 18));
  corner(w, "sw_lat", p.s(93, 17));
  const unsigned station = p.u(110, 4), ship = p.u(114, 8);
  w.withText("stationtype", station, "stationtype_text", stationTypeText(station));
  w.withText("shiptype", ship, "shiptype_text", shipTypeText(ship));
  w.u("interval", p.u(146, 4));
  w.u("quiet", p.u(150, 4));
}

// Types 25 and 26: binary message in one or several slots. The data is what follows the optional
// destination (30 bits) and application id (16 bits); type 26 ends with 20 bits of radio status.
void writeSlotBinary(const Payload& p, unsigned type, AisFields& w) {
  const bool addressed = p.u(38, 1) != 0, structured = p.u(39, 1) != 0;
  const std::size_t head = 40 + (structured ? 16 : 0);
  const std::size_t tail = type == 26 ? 20 : 0;
  const std::size_t copied = p.bits() - head - tail;  // what gpsd copies before dropping the MMSI
  w.b("addressed", addressed);
  w.b("structured", structured);
  w.u("dest_mmsi", addressed ? p.u(40, 30) : 0);
  w.u("app_id", structured ? p.u(addressed ? 70 : 40, 16) : 0);
  const std::size_t start = head + (addressed ? 30 : 0);
  w.dataBits("data", p, start, copied - (addressed ? 30 : 0), head + (copied + 7) / 8 * 8);
  if (type == 26)
    w.u("radio", 0);
}

}  // namespace

bool writePayloadFields(const Payload& p, AisFields& w) {
  switch (p.u(0, 6)) {
    case 6:
      writeType6(p, w);
      return true;
    case 7:
    case 13:
      writeAcknowledge(p, w);
      return true;
    case 8:
      writeType8(p, w);
      return true;
    case 9:
      writeType9(p, w);
      return true;
    case 10:
      w.u("dest_mmsi", p.u(40, 30));
      return true;
    case 12:
      w.u("seqno", p.u(38, 2));
      w.u("dest_mmsi", p.u(40, 30));
      w.b("retransmit", p.u(70, 1) != 0);
      w.text6ToEnd("text", p, 72);
      return true;
    case 14:
      w.text6ToEnd("text", p, 40);
      return true;
    case 15:
      writeType15(p, w);
      return true;
    case 16:
      writeType16(p, w);
      return true;
    case 17:
      writeType17(p, w);
      return true;
    case 20:
      writeType20(p, w);
      return true;
    case 22:
      writeType22(p, w);
      return true;
    case 23:
      writeType23(p, w);
      return true;
    case 25:
    case 26:
      writeSlotBinary(p, p.u(0, 6), w);
      return true;
    default:
      return false;
  }
}

}  // namespace ais
}  // namespace asv
