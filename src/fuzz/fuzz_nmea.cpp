// libFuzzer target for the NMEA framer, the AIS reassembler/decoder, the AIS JSON writers (every type,
// with the type 6 and 8 application payloads) and the ARPA parsers. Not built by CMake; build and run
// from the repository root with:
//
//   clang++ -std=c++17 -fsanitize=fuzzer,address,undefined -I src/include -I /usr/include/eigen3
//   src/fuzz/fuzz_nmea.cpp src/lib/codec/nmea.cpp src/lib/codec/ais.cpp src/lib/codec/ais_json*.cpp
//   src/lib/codec/arpa.cpp
//   ./a.out -max_total_time=20
//
// (a seed corpus helps: `mkdir corpus; cp ../shared/data/ais/libais/*.nmea corpus/; ./a.out corpus ...`)
//
// The input is split into lines; one Decoder lives across the lines of an input (and across inputs,
// with a small max_pending so eviction is exercised), so reassembly state sees arbitrary sequences.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/ais_json.h"
#include "asv_core/codec/arpa.h"
#include "asv_core/codec/nmea.h"

namespace {

asv::ais::Decoder& decoder() {
  static asv::ais::Decoder d([] {
    asv::ais::DecoderConfig c;
    c.max_pending = 4;
    c.fragment_timeout = 2.0;
    return c;
  }());
  return d;
}

void checkKinematics(const asv::ais::Message& m) {
  asv::ais::Kinematics k;
  if (!asv::ais::toKinematics(m, k))
    return;
  // Unknown is NaN, known is finite and in range: never a sentinel turned into a number.
  if (k.has_position && (!(std::fabs(k.lat_deg) <= 90.0) || !(std::fabs(k.lon_deg) <= 180.0)))
    __builtin_trap();
  if (!k.has_position && !std::isnan(k.lat_deg))
    __builtin_trap();
  if (k.has_course && !(k.course >= 0.0 && k.course < 2 * M_PI))
    __builtin_trap();
  // Ships: at most 102.2 kn; SAR aircraft (type 9, whole knots): at most 1021 kn.
  const double max_speed = m.type == 9 ? 526.0 : 60.0;
  if (k.has_speed && !(k.speed >= 0.0 && k.speed < max_speed))
    __builtin_trap();
}

// Both JSON forms of the message's payload fields: within one record's room, and a JSON object's
// brackets balanced (strings are escaped, so brackets inside them do not count).
void checkJson(const asv::ais::Payload& p) {
  static asv::json::Out out(nullptr);
  for (const bool scaled : {false, true}) {
    out.clear();
    out.reserveRecord(0);
    asv::ais::AisFields w(out, scaled);
    asv::ais::writePayloadFields(p, w);
    const std::string_view t = out.text();
    if (t.size() >= asv::json::Out::kRecordRoom)
      __builtin_trap();
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (in_string) {
        if (t[i] == '\\')
          ++i;
        else if (t[i] == '"')
          in_string = false;
      } else if (t[i] == '"') {
        in_string = true;
      } else if (t[i] == '[' || t[i] == '{') {
        ++depth;
      } else if (t[i] == ']' || t[i] == '}') {
        --depth;
      }
    }
    if (depth != 0 || in_string)
      __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  static asv::ais::StaticStore store;
  asv::nmea::Sentence s;
  asv::ais::Message m;
  double now = 0.0;
  std::size_t begin = 0;
  while (begin <= input.size()) {
    std::size_t end = input.find('\n', begin);
    if (end == std::string_view::npos)
      end = input.size();
    const std::string_view line = input.substr(begin, end - begin);
    begin = end + 1;
    now += 0.5;
    // Every start position, as the CLI's resynchronisation does.
    std::size_t pos = 0;
    while ((pos = asv::nmea::findSentenceStart(line, pos)) != std::string_view::npos) {
      const asv::nmea::Reject r = asv::nmea::parseSentence(line.substr(pos), s);
      if (r != asv::nmea::Reject::kNone) {
        ++pos;
        continue;
      }
      if (s.end == 0 || s.field_count == 0 || s.field_count > asv::nmea::kMaxFields)
        __builtin_trap();
      if (decoder().feed(s, now, m) == asv::ais::Status::kMessage) {
        checkKinematics(m);
        checkJson(decoder().payload());
        store.update(m);
      }
      asv::arpa::TrackedTarget t;
      if (asv::arpa::parseTtm(s, t) == asv::arpa::Error::kNone)
        asv::arpa::toTrue(t, 1.0);
      asv::arpa::TargetPosition p;
      asv::arpa::parseTll(s, p);
      asv::arpa::OwnShipData o;
      asv::arpa::parseOsd(s, o);
      pos += s.end;
    }
    if (end == input.size())
      break;
  }
  if (decoder().pendingCount() > decoder().config().max_pending)
    __builtin_trap();
  return 0;
}
