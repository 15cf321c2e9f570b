// AIS (ITU-R M.1371) decoding of AIVDM/AIVDO sentences: six-bit armour, multi-fragment reassembly,
// all 27 message types. Types 1-5, 9, 11, 12, 14, 18, 19, 21, 24 and 27 are decoded into typed
// bodies; the others (binary, acknowledgement, interrogation and link-management messages) are
// checked for length as gpsd 3.22 checks them and keep their fields in the payload bits, which
// ais_json.h prints field by field (Decoder::payload()).
//
// Every message keeps the raw (unscaled, integer) fields exactly as transmitted, because tools such
// as `asv_ais_decode -u` must reproduce gpsd's unscaled output and because "not available" must stay
// distinguishable from a value. SI accessors return std::nullopt for the "not available" sentinels
// (lat 91, lon 181, speed 1023, course 3600, heading 511, turn -128) and for out-of-range values;
// they never turn a sentinel into a number (README.md, Conventions).
//
// No allocation on the decode path: text fields are fixed-capacity strings, fragments are stored in
// buffers reserved when the Decoder is built.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include "asv_core/codec/nmea.h"

namespace asv {
namespace ais {

// Longest reassembled payload [armoured characters]: 5 slots of 256 bits is 1008 bits = 168
// characters; twice that leaves room for non-conforming senders and still bounds memory.
constexpr std::size_t kMaxPayloadChars = 336;
constexpr std::size_t kMaxPayloadBits = kMaxPayloadChars * 6;
constexpr int kMaxFragments = 9;  // the fragment count is one digit

// Text of fixed capacity (AIS text fields are at most 20 six-bit characters, 34 for a type 21 name
// with its extension), so decoding never allocates.
template <std::size_t N>
class FixedString {
public:
  void clear() { size_ = 0; }
  void push_back(char c) {
    if (size_ < N)
      data_[size_++] = c;
  }
  void resize(std::size_t n) { size_ = n < size_ ? n : size_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  char back() const { return data_[size_ - 1]; }
  std::string_view view() const { return std::string_view(data_.data(), size_); }
  void assign(std::string_view s) {
    size_ = 0;
    for (char c : s)
      push_back(c);
  }
  bool operator==(std::string_view s) const { return view() == s; }

private:
  std::array<char, N> data_{};
  std::size_t size_ = 0;
};

using Text20 = FixedString<20>;
using Text7 = FixedString<7>;
using Text34 = FixedString<34>;

// The payload bits of one message, unpacked from the six-bit armour.
class Payload {
public:
  // Appends armoured characters; false on a character outside the armour alphabet or overflow.
  bool append(std::string_view armoured);
  // Drops the `fill` padding bits at the end (0..5); they stay visible to the raw reads, as in gpsd's
  // bit buffer (binary data of types 17, 25 and 26 prints them).
  void dropFill(int fill) { nbits_ = static_cast<std::size_t>(fill) > nbits_ ? 0 : nbits_ - fill; }
  void clear() { nbits_ = visible_ = 0; }
  std::size_t bits() const { return nbits_; }
  // Longest six-bit text a payload can hold [characters].
  static constexpr std::size_t kMaxTextChars = kMaxPayloadBits / 6;

  // Unsigned/signed (two's complement) field of `len` bits (<= 32) at bit `start`. A field that runs
  // past the end reads only the bits present, right-aligned, as gpsd does for short type 1-3
  // messages (163 bits), so the output matches it; bits past the end never read as data.
  std::uint32_t u(std::size_t start, std::size_t len) const;
  std::int32_t s(std::size_t start, std::size_t len) const;
  // Fields read as gpsd reads its bit buffer: past the end of the payload come the fill bits as
  // sent, then zeros, left-aligned. gpsd decodes fields of some types without checking
  // the length.
  std::uint32_t ur(std::size_t start, std::size_t len) const;
  std::int32_t sr(std::size_t start, std::size_t len) const;
  // The 8 bits at `start` read as ur(); bits at or after `limit` read as 0 when `limit` is not 0.
  std::uint32_t rawByte(std::size_t start, std::size_t limit = 0) const;
  // `count` six-bit characters from `start`, stopping at the first '@' (the ITU padding character)
  // and the payload end; trailing spaces are trimmed when `trim`.
  template <std::size_t N>
  void text(std::size_t start, std::size_t count, FixedString<N>& out, bool trim = true) const {
    out.clear();
    appendText(start, count, out, trim);
  }
  template <std::size_t N>
  void appendText(std::size_t start, std::size_t count, FixedString<N>& out, bool trim = true) const {
    for (std::size_t i = 0; i < count && start + 6 * (i + 1) <= nbits_; ++i) {
      char c = sixbitChar(u(start + 6 * i, 6));
      if (c == '@')
        break;
      out.push_back(c);
    }
    if (trim)
      trimRight(out);
  }
  template <std::size_t N>
  static void trimRight(FixedString<N>& out) {
    std::size_t n = out.size();
    while (n > 0) {
      char c = out.view()[n - 1];
      if (c != ' ' && c != '@')
        break;
      --n;
    }
    out.resize(n);
  }
  static char sixbitChar(std::uint32_t v);

private:
  // `len` (<= 32) bits at `start` as stored, unchecked.
  std::uint32_t extract(std::size_t start, std::size_t len) const;

  std::array<std::uint8_t, kMaxPayloadBits / 8 + 8> bytes_{};
  std::size_t nbits_ = 0;
  std::size_t visible_ = 0;  // bits readable by ur(): the payload and its fill bits
};

// ---- Messages (raw fields named as in ITU-R M.1371 / gpsd; units in the comments) ----

constexpr std::int32_t kLatNotAvailable = 91 * 600000;   // 1/10000 min
constexpr std::int32_t kLonNotAvailable = 181 * 600000;  // 1/10000 min
constexpr std::uint32_t kSpeedNotAvailable = 1023;       // 1/10 kn
constexpr std::uint32_t kCourseNotAvailable = 3600;      // 1/10 deg
constexpr std::uint32_t kHeadingNotAvailable = 511;      // deg
constexpr std::int32_t kTurnNotAvailable = -128;

// SI views of the raw fields, shared by the position-carrying messages.
std::optional<double> latDeg(std::int32_t raw_lat);           // 1/10000 min -> deg
std::optional<double> lonDeg(std::int32_t raw_lon);           // 1/10000 min -> deg
std::optional<double> speedMps(std::uint32_t raw_speed);      // 1/10 kn -> m/s
std::optional<double> courseRad(std::uint32_t raw_course);    // 1/10 deg -> rad, nautical
std::optional<double> headingRad(std::uint32_t raw_heading);  // deg -> rad, nautical
// Rate of turn [rad/s], positive turning right (clockwise). ROT_AIS = 4.733 sqrt(deg/min); -128
// (no information) and +-127 (turning faster than 5 deg/30 s, no rate indicator) have no value.
std::optional<double> rateOfTurn(std::int32_t raw_turn);

// Types 1, 2, 3: class A position report.
struct PositionReportA {
  std::uint8_t status = 15;    // navigational status 0..15
  std::int32_t turn = -128;    // ROT_AIS
  std::uint32_t speed = 1023;  // 1/10 kn
  bool accuracy = false;
  std::int32_t lon = kLonNotAvailable;  // 1/10000 min
  std::int32_t lat = kLatNotAvailable;  // 1/10000 min
  std::uint32_t course = 3600;          // 1/10 deg
  std::uint32_t heading = 511;          // deg
  std::uint8_t second = 60;             // UTC second of the report, 60 = not available
  std::uint8_t maneuver = 0;
  bool raim = false;
  std::uint32_t radio = 0;
};

// Types 4 (base station report) and 11 (UTC/date response) share this layout.
struct BaseStationReport {
  std::uint32_t year = 0, month = 0, day = 0, hour = 24, minute = 60, second = 60;
  bool accuracy = false;
  std::int32_t lon = kLonNotAvailable;
  std::int32_t lat = kLatNotAvailable;
  std::uint8_t epfd = 0;
  bool raim = false;
  std::uint32_t radio = 0;
};

// Type 5: static and voyage related data.
struct StaticVoyageData {
  std::uint8_t ais_version = 0;
  std::uint32_t imo = 0;
  Text7 callsign;
  Text20 shipname;
  std::uint8_t shiptype = 0;
  std::uint32_t to_bow = 0, to_stern = 0, to_port = 0, to_starboard = 0;  // m
  std::uint8_t epfd = 0;
  std::uint32_t month = 0, day = 0, hour = 24, minute = 60;  // ETA, UTC
  std::uint32_t draught = 0;                                 // 1/10 m
  Text20 destination;
  bool dte = false;
};

// Type 18: class B position report; type 19: extended class B report.
struct PositionReportB {
  std::uint32_t reserved = 0;  // regional reserved (8 bits)
  std::uint32_t speed = 1023;
  bool accuracy = false;
  std::int32_t lon = kLonNotAvailable;
  std::int32_t lat = kLatNotAvailable;
  std::uint32_t course = 3600;
  std::uint32_t heading = 511;
  std::uint8_t second = 60;
  std::uint32_t regional = 0;  // 2 bits in type 18, 4 in type 19
  // Type 18 only
  bool cs = false, display = false, dsc = false, band = false, msg22 = false;
  std::uint32_t radio = 0;
  // Type 19 only
  Text20 shipname;
  std::uint8_t shiptype = 0;
  std::uint32_t to_bow = 0, to_stern = 0, to_port = 0, to_starboard = 0;
  std::uint8_t epfd = 0;
  bool dte = false;
  // Both
  bool assigned = false;
  bool raim = false;
};

// Type 21: aid to navigation.
struct AidToNavigation {
  std::uint8_t aid_type = 0;
  Text34 name;  // 20 characters plus the name extension
  bool accuracy = false;
  std::int32_t lon = kLonNotAvailable;
  std::int32_t lat = kLatNotAvailable;
  std::uint32_t to_bow = 0, to_stern = 0, to_port = 0, to_starboard = 0;
  std::uint8_t epfd = 0;
  std::uint8_t second = 60;
  bool off_position = false;
  std::uint32_t regional = 0;
  bool raim = false, virtual_aid = false, assigned = false;
};

// Type 24: class B static data, part A (name) or part B (the rest).
struct StaticDataReport {
  std::uint8_t part = 0;      // 0 = A, 1 = B
  Text20 shipname;            // part A
  std::uint8_t shiptype = 0;  // part B from here
  Text7 vendorid;
  std::uint32_t model = 0, serial = 0;
  Text7 callsign;
  std::uint32_t to_bow = 0, to_stern = 0, to_port = 0, to_starboard = 0;
  std::uint32_t mothership_mmsi = 0;  // instead of the dimensions for auxiliary craft (98XXXYYYY)
};

// Type 27: long-range broadcast (satellite). Coarser units than types 1-3.
struct LongRangeReport {
  bool accuracy = false, raim = false;
  std::uint8_t status = 15;
  std::int32_t lon = 181 * 600;  // 1/10 min
  std::int32_t lat = 91 * 600;   // 1/10 min
  std::uint32_t speed = 63;      // kn, 63 = not available
  std::uint32_t course = 511;    // deg, 511 = not available
  bool gnss = false;             // GNSS position status bit as sent: 0 = current GNSS fix
};

// Type 9: standard SAR aircraft position report.
struct SarAircraftReport {
  std::uint32_t alt = 4095;    // altitude [m], 4095 = not available, 4094 = 4094 m or higher
  std::uint32_t speed = 1023;  // kn (whole knots), 1023 = not available, 1022 = 1022 kn or faster
  bool accuracy = false;
  std::int32_t lon = kLonNotAvailable;
  std::int32_t lat = kLatNotAvailable;
  std::uint32_t course = 3600;  // 1/10 deg
  std::uint8_t second = 60;
  std::uint32_t regional = 0;
  bool dte = false, assigned = false, raim = false;
  std::uint32_t radio = 0;
};

// Types 12 (addressed) and 14 (broadcast): safety-related text.
struct SafetyText {
  std::uint8_t seqno = 0;       // type 12 only
  std::uint32_t dest_mmsi = 0;  // type 12 only
  bool retransmit = false;      // type 12 only
  FixedString<Payload::kMaxTextChars> text;
};

// Types 6, 7, 8, 10, 13, 15, 16, 17, 20, 22, 23, 25 and 26: fields stay in the payload bits
// (Decoder::payload(), ais_json.h); the application identifier of the binary types 6 and 8 is kept
// here to route them (DAC/FID 1/31 is weather).
struct PayloadMessage {
  std::uint32_t dac = 0, fid = 0;  // types 6 and 8 only
};

// Type 8, DAC 1 FID 31: IMO289 (SN.1/Circ.289) meteorological and hydrographic data, from a weather
// station or buoy. Raw fields as sent, defaults the "not available" codes. Decoded from the payload by
// decodeMetHydro31(); the SI accessors return std::nullopt for "not available" and reserved codes.
struct MetHydroReport {
  std::int32_t lon = 181 * 60000;                // 1/1000 min, 181 deg = not available
  std::int32_t lat = 91 * 60000;                 // 1/1000 min, 91 deg = not available
  bool accuracy = false;                         // position accuracy: true = high (< 10 m)
  std::uint8_t day = 0, hour = 24, minute = 60;  // UTC of the observation; 0, 24, 60 = not available
  std::uint8_t wspeed = 127, wgust = 127;        // kn (10-min mean, 10-min max), 126 = 126 kn or more
  std::uint16_t wdir = 360, wgustdir = 360;      // deg, direction the wind blows from, 360 = n/a
  std::int16_t airtemp = -1024;                  // 0.1 degC, -600..600
  std::uint8_t humidity = 101;                   // %, 0..100
  std::int16_t dewpoint = 501;                   // 0.1 degC, -200..500
  std::uint16_t pressure = 511;     // hPa - 799: 0 = 799 hPa or less, 1..401, 402 = 1201 hPa or more
  std::uint8_t pressuretend = 3;    // 0 steady, 1 decreasing, 2 increasing, 3 = not available
  bool visgreater = false;          // the visibility is more than the value sent (sensor range reached)
  std::uint8_t visibility = 127;    // 0.1 NM, 0..126
  std::uint16_t waterlevel = 4001;  // 0.01 m + 10 m: 0..4000 is -10.00..+30.00 m (incl. tide)
  std::uint8_t leveltrend = 3;      // as pressuretend
  std::uint8_t cspeed = 255, cspeed2 = 255, cspeed3 = 255;  // current 0.1 kn, 251 = 25.1 kn or more
  std::uint16_t cdir = 360, cdir2 = 360, cdir3 = 360;       // deg
  std::uint8_t cdepth2 = 31, cdepth3 = 31;                  // m below the surface, 0..30
  std::uint8_t waveheight = 255, swellheight = 255;         // significant height 0.1 m, 251 = 25.1 m+
  std::uint8_t waveperiod = 63, swellperiod = 63;           // s, 0..60
  std::uint16_t wavedir = 360, swelldir = 360;              // deg
  std::uint8_t seastate = 13;                               // Beaufort 0..12, 13 = not available
  std::int16_t watertemp = 501;                             // 0.1 degC, -100..500
  std::uint8_t preciptype = 7;   // WMO 306 code table 4.201: 1 rain ... 5 snow, 7 = not available
  std::uint16_t salinity = 501;  // 0.1 permille, 0..500
  std::uint8_t ice = 3;          // 0 no, 1 yes, 3 = not available

  std::optional<double> latDeg() const;
  std::optional<double> lonDeg() const;
  std::optional<double> windSpeedMps() const;  // 126 ("126 kn or more") gives 126 kn
  std::optional<double> windGustMps() const;
  std::optional<double> windDirectionRad() const;  // nautical, the direction the wind blows from
  // Horizontal visibility [m]; with `visgreater` set, the visibility is more than this.
  std::optional<double> visibilityM() const;
  std::optional<double> airTemperatureC() const;
  std::optional<double> airPressureHpa() const;  // 799 and 1201 mean "or less" and "or more"
  std::optional<int> seaStateBeaufort() const;
  std::optional<double> waterLevelM() const;  // above the local chart datum, tide included
};

// Decodes a type 8 DAC 1 FID 31 payload (`p` whole, from the message type). False, leaving `out`
// unchanged, for another type or DAC/FID, or a payload shorter than the 350 bits that hold the
// fields (gpsd reads short ones anyway, zeros and fill bits in place of the missing fields) or
// longer than gpsd's 1008.
bool decodeMetHydro31(const Payload& p, MetHydroReport& out);

using Body =
    std::variant<PositionReportA, BaseStationReport, StaticVoyageData, PositionReportB, AidToNavigation,
                 StaticDataReport, LongRangeReport, SarAircraftReport, SafetyText, PayloadMessage>;

struct Message {
  std::uint8_t type = 0;
  std::uint8_t repeat = 0;
  std::uint32_t mmsi = 0;
  char channel = '\0';     // 'A'/'B' (also '1'/'2'), '\0' when the sentence left it empty
  bool own_ship = false;   // AIVDO
  bool has_time = false;   // from the tag block of the (last) sentence
  double unix_time = 0.0;  // [s]
  Body body;
};

// Kinematic SI view of a position report (types 1-3, 4, 9, 11, 18, 19, 21, 27), for the tracker. Unknown
// quantities are NaN with their has_ flag false.
struct Kinematics {
  std::uint32_t mmsi = 0;
  bool has_position = false;
  double lat_deg = std::numeric_limits<double>::quiet_NaN();
  double lon_deg = std::numeric_limits<double>::quiet_NaN();
  bool has_speed = false;
  double speed = std::numeric_limits<double>::quiet_NaN();  // [m/s] over ground
  bool has_course = false;
  double course = std::numeric_limits<double>::quiet_NaN();  // [rad] course over ground, nautical
  bool has_heading = false;
  double heading = std::numeric_limits<double>::quiet_NaN();  // [rad] true heading, nautical
  bool has_turn = false;
  double rate_of_turn = std::numeric_limits<double>::quiet_NaN();  // [rad/s], positive clockwise
  int turn_direction = 0;  // sign of the turn when known at least as "fast left/right"
};

// False for messages without a position (5, 24 and the payload-only types).
bool toKinematics(const Message& m, Kinematics& out);

// ---- Decoder ----

struct DecoderConfig {
  // A multi-sentence message whose next fragment does not arrive within this time is dropped [s].
  // Fragments of one message are sent back to back (same slot or consecutive slots), so a few
  // seconds is generous; it only matters when the caller provides a clock.
  double fragment_timeout = 10.0;
  // Messages being reassembled at once. Bounds memory against floods of first fragments; two
  // channels and ten sequence ids make 20 legitimate ones, the rest is margin for several receivers.
  std::size_t max_pending = 64;
  // Key reassemblies also by the tag-block source (s:), so that interleaved streams from several
  // receivers do not mix fragments.
  bool key_by_source = true;

  void validate() const;
};

enum class Status : std::uint8_t {
  kMessage = 0,  // `out` holds a decoded message
  kPending,      // fragment stored, message not complete yet
  kNotAis,       // not a VDM/VDO sentence (not counted as an error)
  kBadFields,    // wrong field count or malformed fragment count/number/sequence id
  kBadFill,      // fill bits not 0..5
  kBadArmour,    // payload character outside the six-bit alphabet, or too long
  kEmptyPayload,
  kOrphanFragment,   // a later fragment with no first fragment pending
  kOutOfOrder,       // fragment number not the next expected: the whole message is dropped
  kUnsupportedType,  // well-formed, but a type this decoder does not decode
  kTooShort,         // fewer bits than the type needs
  kBadPart,          // type 24 part number other than 0/1
  kTooLong,          // more bits than the type allows (gpsd 3.22's limits)
  kCount
};

const char* statusText(Status s);

struct Counters {
  std::uint64_t sentences = 0;     // VDM/VDO sentences fed
  std::uint64_t messages = 0;      // messages decoded
  std::uint64_t pending = 0;       // fragments stored
  std::uint64_t orphans = 0;       // later fragments without a first one
  std::uint64_t out_of_order = 0;  // fragments out of sequence (message dropped)
  std::uint64_t restarted = 0;     // first fragment while one with the same key was pending
  std::uint64_t timeouts = 0;      // incomplete messages dropped by the timeout
  std::uint64_t evicted = 0;       // incomplete messages dropped because max_pending was reached
  std::uint64_t bad_fields = 0;
  std::uint64_t bad_fill = 0;
  std::uint64_t bad_armour = 0;
  std::uint64_t empty_payload = 0;
  std::uint64_t unsupported = 0;
  std::uint64_t too_short = 0;
  std::uint64_t bad_part = 0;
  std::uint64_t too_long = 0;
};

// Decodes one complete payload (all fragments joined, fill bits removed) into `out`.
Status decodePayload(const Payload& payload, Message& out);

class Decoder {
public:
  explicit Decoder(const DecoderConfig& config = DecoderConfig());

  // Feeds one framed sentence. `now` [s] is the caller's clock for the fragment timeout (a receive
  // time, or the tag-block time); pass the same value (e.g. 0) to disable timeouts.
  Status feed(const nmea::Sentence& sentence, double now, Message& out);
  // Convenience: frame and feed one line. Framing errors come back in `reject`.
  Status feedLine(std::string_view line, double now, Message& out, nmea::Reject* reject = nullptr);

  // Drops incomplete messages older than the timeout.
  void expire(double now);
  // Drops every incomplete message, uncounted (the caller's clock went backwards).
  void clearPending();
  std::size_t pendingCount() const;
  const Counters& counters() const { return counters_; }
  const DecoderConfig& config() const { return config_; }
  // The payload of the message last returned with Status::kMessage (valid until the next feed).
  const Payload& payload() const { return payload_; }

private:
  struct Pending {
    bool used = false;
    std::uint64_t key = 0;
    int count = 0;  // fragments in the message
    int next = 0;   // next fragment number expected
    double started = 0.0;
    std::uint64_t order = 0;  // insertion order, for eviction
    std::size_t nchars = 0;
    std::array<char, kMaxPayloadChars> chars;
  };

  Status complete(std::string_view armoured, int fill, Message& out);
  Status count(Status s);

  DecoderConfig config_;
  nmea::FramerConfig framer_;
  Counters counters_;
  std::vector<Pending> pending_;
  std::size_t npending_ = 0;
  std::uint64_t order_ = 0;
  Payload payload_;
  nmea::Sentence sentence_;
};

// ---- Static data per ship (types 5, 19, 24A/B merged) ----

struct ShipStatic {
  std::uint32_t mmsi = 0;
  Text20 shipname;
  Text7 callsign;
  std::uint32_t imo = 0;
  std::uint8_t shiptype = 0;
  std::uint32_t to_bow = 0, to_stern = 0, to_port = 0, to_starboard = 0;  // m
  Text20 destination;
  std::uint32_t draught = 0;  // 1/10 m
  bool has_name = false, has_type = false, has_dimensions = false;

  double length() const { return static_cast<double>(to_bow + to_stern); }     // [m]
  double beam() const { return static_cast<double>(to_port + to_starboard); }  // [m]
};

struct StaticStoreConfig {
  // Ships remembered; the least recently updated is forgotten beyond this.
  std::size_t max_ships = 10000;
  void validate() const;
};

class StaticStore {
public:
  explicit StaticStore(const StaticStoreConfig& config = StaticStoreConfig());
  // Merges a type 5, 19 or 24 message; returns the merged record, or nullptr for other types.
  const ShipStatic* update(const Message& m);
  const ShipStatic* find(std::uint32_t mmsi) const;
  std::size_t size() const { return ships_.size(); }

private:
  struct Entry {
    ShipStatic data;
    std::uint64_t stamp = 0;
  };
  void evictIfFull();
  StaticStoreConfig config_;
  std::unordered_map<std::uint32_t, Entry> ships_;
  std::uint64_t stamp_ = 0;
};

// Text legends as gpsd prints them (`status_text`, `shiptype_text`, `epfd_text`, `aid_type_text`).
const char* navStatusText(unsigned status);
const char* shipTypeText(unsigned shiptype);
const char* epfdText(unsigned epfd);
const char* aidTypeText(unsigned aid_type);
const char* stationTypeText(unsigned station_type);  // type 23

}  // namespace ais
}  // namespace asv
