// NMEA 0183 sentence framing: `$`/`!` sentences, checksums, NMEA 4 tag blocks, field splitting.
//
// The framer is on the hot path of every AIS and radar input, so it never allocates: a Sentence is a
// set of std::string_view into the caller's line, valid as long as that line is. A line that cannot
// be a sentence is rejected with a Reject reason (never logged: the caller decides what to report).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace asv {
namespace nmea {

// IEC 61162-1 limit for one sentence (start character to <LF>). Real receivers exceed it (long
// USCG suffixes, AIS payloads of 80+ characters), so the framer tolerates FramerConfig::max_length.
constexpr std::size_t kStandardMaxLength = 82;
// Fields per sentence, address included. TTM has 16; proprietary sentences rarely exceed 30.
constexpr std::size_t kMaxFields = 40;

struct FramerConfig {
  // Longest accepted line [bytes], tag block and suffix included, line terminator excluded. 512
  // covers every receiver seen in the wild; longer input is line noise or concatenated sentences.
  std::size_t max_length = 512;
  // A sentence without `*hh` is rejected (IEC 61162-1 makes it mandatory for `!` sentences and every
  // AIS/ARPA source sends it). False accepts `$` sentences without one (Sentence::has_checksum).
  bool require_checksum = true;
  // Text after the checksum (e.g. USCG `,d-109,S2105,...` receiver metadata) is kept as a suffix
  // instead of rejecting the line, as gpsd does.
  bool allow_suffix = true;

  // Throws std::invalid_argument when a value is out of range.
  void validate() const;
};

// Why a line is not a sentence. Keep rejectText() in step.
enum class Reject : std::uint8_t {
  kNone = 0,
  kEmpty,              // nothing but whitespace
  kTooLong,            // longer than FramerConfig::max_length
  kNonPrintable,       // a byte outside 0x20..0x7e: binary data or a corrupted serial line
  kNoStart,            // no `$` or `!` where the sentence should start
  kNoChecksum,         // no `*hh` and FramerConfig::require_checksum
  kBadChecksumFormat,  // `*` not followed by two hex digits (typically a truncated line)
  kBadChecksum,        // checksum mismatch
  kBadAddress,         // address field empty, too long or not alphanumeric
  kTooManyFields,      // more than kMaxFields fields
  kBadTagBlock,        // malformed `\...\` tag block (unterminated, bad field, bad number)
  kTagBlockChecksum,   // tag block checksum missing or wrong
  kCount
};

const char* rejectText(Reject r);

// NMEA 4 tag block (`\s:src,c:1418169601,g:1-2-1604*hh\`). Only the fields the stack uses are
// parsed; the raw text is kept for the rest.
struct TagBlock {
  bool present = false;
  std::string_view raw;     // between the backslashes, checksum excluded
  std::string_view source;  // s: receiver/station id, empty when absent
  bool has_time = false;
  double unix_time = 0.0;  // c: [s] since 1970 (values > 1e11 are taken as milliseconds)
  bool has_group = false;
  int group_sentence = 0;  // g: this sentence's number in the group (1-based)
  int group_count = 0;     // g: sentences in the group
  int group_id = 0;        // g: group id
};

struct Sentence {
  char start = '\0';        // '$' (parametric) or '!' (encapsulated)
  std::string_view talker;  // "AI", "RA", "GP"...; "P" for proprietary sentences
  std::string_view type;    // "VDM", "TTM"...; the manufacturer + type for proprietary ones
  std::string_view body;    // between the start character and `*`, exclusive
  std::string_view suffix;  // after the checksum (trimmed), empty when none
  bool has_checksum = false;
  std::size_t end = 0;  // offset in the input line just past the checksum (or the body)
  TagBlock tag;
  std::size_t field_count = 0;  // fields[0] is the address ("AIVDM")
  std::array<std::string_view, kMaxFields> fields;

  // Field i (0 = address); empty when absent, so optional trailing fields read as empty.
  std::string_view field(std::size_t i) const { return i < field_count ? fields[i] : std::string_view(); }
  bool is(std::string_view sentence_type) const { return type == sentence_type; }
};

// Frames one line (CR/LF and surrounding whitespace tolerated). The line must start with the tag
// block or the start character. On kNone `out` is filled; otherwise its contents are unspecified.
Reject parseSentence(std::string_view line, Sentence& out, const FramerConfig& config = {});

// Position of the next place a sentence could start at or after `from`: a `$`/`!`, or the opening
// `\` of a tag block directly in front of one. npos when none. Lets a reader resynchronise after
// garbage or a truncated sentence on the same line without losing the valid sentence behind it.
std::size_t findSentenceStart(std::string_view line, std::size_t from = 0);

// XOR of the bytes, as in the `*hh` checksum.
std::uint8_t checksum(std::string_view data);

// Parses a field as a number. Leading/trailing spaces are tolerated (radars pad fields); an empty
// or malformed field returns false and leaves `value` alone.
bool parseDouble(std::string_view field, double& value);
bool parseInt(std::string_view field, long& value);

// "ddmm.mmm" (latitude, is_lat) or "dddmm.mmm" with its hemisphere field (N/S, E/W) -> signed degrees;
// false for an empty, malformed or out-of-range value (minutes >= 60, beyond 90/180 deg).
bool parseLatLon(std::string_view value, std::string_view hemisphere, bool is_lat, double& degrees);

// First non-space character of a one-letter field (a status, a unit, a hemisphere); '\0' when empty.
char letter(std::string_view field);

// Trims ASCII spaces (and tabs) on both ends.
std::string_view trim(std::string_view s);

}  // namespace nmea
}  // namespace asv
