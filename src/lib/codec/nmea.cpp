#include "asv_core/codec/nmea.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace asv {
namespace nmea {

namespace {

inline bool isPrintable(unsigned char c) {
  return c >= 0x20 && c <= 0x7e;
}

inline int hexValue(char c) {
  if (c >= '0' && c <= '9')
    return c - '0';
  if (c >= 'A' && c <= 'F')
    return c - 'A' + 10;
  if (c >= 'a' && c <= 'f')
    return c - 'a' + 10;
  return -1;
}

inline bool isAlnum(char c) {
  return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

// Strips the line terminator and any surrounding whitespace (serial captures carry "\r\n", files
// written on other systems a stray "\r").
std::string_view stripLine(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r' || s[b] == '\n'))
    ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r' || s[e - 1] == '\n'))
    --e;
  return s.substr(b, e - b);
}

bool parseUnsigned(std::string_view s, long long& v) {
  if (s.empty())
    return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && v >= 0;
}

// "1-2-1604": sentence number, sentence count, group id.
bool parseGroup(std::string_view v, TagBlock& tag) {
  long long n[3];
  for (int i = 0; i < 3; ++i) {
    std::size_t dash = i < 2 ? v.find('-') : v.size();
    if (dash == std::string_view::npos)
      return false;
    if (!parseUnsigned(v.substr(0, dash), n[i]))
      return false;
    v.remove_prefix(i < 2 ? dash + 1 : dash);
  }
  if (n[0] < 1 || n[1] < 1 || n[0] > n[1] || n[1] > 99 || n[2] > 1000000)
    return false;
  tag.has_group = true;
  tag.group_sentence = static_cast<int>(n[0]);
  tag.group_count = static_cast<int>(n[1]);
  tag.group_id = static_cast<int>(n[2]);
  return true;
}

Reject parseTagBlock(std::string_view content, TagBlock& tag) {
  std::size_t star = content.rfind('*');
  if (star == std::string_view::npos || star + 3 != content.size())
    return Reject::kTagBlockChecksum;
  int h = hexValue(content[star + 1]), l = hexValue(content[star + 2]);
  if (h < 0 || l < 0)
    return Reject::kTagBlockChecksum;
  std::string_view fields = content.substr(0, star);
  if (checksum(fields) != static_cast<std::uint8_t>(h * 16 + l))
    return Reject::kTagBlockChecksum;
  tag.present = true;
  tag.raw = fields;
  while (!fields.empty()) {
    std::size_t comma = fields.find(',');
    std::string_view f = fields.substr(0, comma);
    fields.remove_prefix(comma == std::string_view::npos ? fields.size() : comma + 1);
    if (f.size() < 2 || f[1] != ':' || !isAlnum(f[0]))
      return Reject::kBadTagBlock;
    std::string_view v = f.substr(2);
    switch (f[0]) {
      case 's':
        tag.source = v;
        break;
      case 'c': {
        long long t;
        if (!parseUnsigned(v, t))
          return Reject::kBadTagBlock;
        tag.has_time = true;
        // Some receivers (e.g. Spire) send milliseconds; no plausible seconds value is that large.
        tag.unix_time = t > 100000000000LL ? static_cast<double>(t) / 1000.0 : static_cast<double>(t);
        break;
      }
      case 'g':
      case 'G':
        if (!parseGroup(v, tag))
          return Reject::kBadTagBlock;
        break;
      default:
        break;  // d, n, r, t, q, T, i...: kept in raw, not needed by the stack
    }
  }
  return Reject::kNone;
}

}  // namespace

void FramerConfig::validate() const {
  if (max_length < kStandardMaxLength || max_length > 65536)
    throw std::invalid_argument("nmea::FramerConfig::max_length must be in [82, 65536]");
}

const char* rejectText(Reject r) {
  switch (r) {
    case Reject::kNone:
      return "ok";
    case Reject::kEmpty:
      return "empty line";
    case Reject::kTooLong:
      return "line too long";
    case Reject::kNonPrintable:
      return "non-printable (binary) character";
    case Reject::kNoStart:
      return "no sentence start ($ or !)";
    case Reject::kNoChecksum:
      return "no checksum (truncated sentence?)";
    case Reject::kBadChecksumFormat:
      return "malformed checksum (truncated sentence?)";
    case Reject::kBadChecksum:
      return "checksum mismatch";
    case Reject::kBadAddress:
      return "bad address field";
    case Reject::kTooManyFields:
      return "too many fields";
    case Reject::kBadTagBlock:
      return "malformed tag block";
    case Reject::kTagBlockChecksum:
      return "tag block checksum missing or wrong";
    case Reject::kCount:
      break;
  }
  return "unknown";
}

std::uint8_t checksum(std::string_view data) {
  std::uint8_t cs = 0;
  for (char c : data)
    cs ^= static_cast<std::uint8_t>(c);
  return cs;
}

Reject parseSentence(std::string_view raw_line, Sentence& out, const FramerConfig& config) {
  const std::string_view line = stripLine(raw_line);
  if (line.empty())
    return Reject::kEmpty;
  if (line.size() > config.max_length)
    return Reject::kTooLong;

  out.tag = TagBlock();
  std::size_t pos = 0;
  if (line[0] == '\\') {
    std::size_t close = line.find('\\', 1);
    if (close == std::string_view::npos)
      return Reject::kBadTagBlock;
    for (std::size_t i = 1; i < close; ++i)
      if (!isPrintable(static_cast<unsigned char>(line[i])))
        return Reject::kNonPrintable;
    Reject r = parseTagBlock(line.substr(1, close - 1), out.tag);
    if (r != Reject::kNone)
      return r;
    pos = close + 1;
  }
  if (pos >= line.size() || (line[pos] != '$' && line[pos] != '!'))
    return Reject::kNoStart;
  out.start = line[pos];

  // One pass over the body: printable check, checksum and field split together, because this loop
  // is the framer's whole cost per sentence.
  const char* p = line.data();
  const std::size_t n = line.size();
  const std::size_t body_begin = pos + 1;
  std::size_t i = body_begin;
  std::size_t field_begin = body_begin;
  std::size_t nf = 0;
  std::uint8_t cs = 0;
  for (; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(p[i]);
    if (c == '*')
      break;
    if (!isPrintable(c))
      return Reject::kNonPrintable;
    cs ^= c;
    if (c == ',') {
      if (nf + 1 >= kMaxFields)
        return Reject::kTooManyFields;
      out.fields[nf++] = std::string_view(p + field_begin, i - field_begin);
      field_begin = i + 1;
    }
  }
  out.fields[nf++] = std::string_view(p + field_begin, i - field_begin);
  out.field_count = nf;
  out.body = std::string_view(p + body_begin, i - body_begin);
  out.suffix = std::string_view();

  if (i < n) {  // at '*'
    if (i + 3 > n)
      return Reject::kBadChecksumFormat;
    const int h = hexValue(p[i + 1]), l = hexValue(p[i + 2]);
    if (h < 0 || l < 0)
      return Reject::kBadChecksumFormat;
    if (cs != static_cast<std::uint8_t>(h * 16 + l))
      return Reject::kBadChecksum;
    out.has_checksum = true;
    out.end = i + 3;
    if (out.end < n) {
      for (std::size_t k = out.end; k < n; ++k)
        if (!isPrintable(static_cast<unsigned char>(p[k])))
          return Reject::kNonPrintable;
      if (!config.allow_suffix)
        return Reject::kBadChecksumFormat;
      out.suffix = trim(line.substr(out.end));
    }
  } else {
    if (config.require_checksum)
      return Reject::kNoChecksum;
    out.has_checksum = false;
    out.end = n;
  }

  // Offsets are relative to the stripped line; make `end` relative to the caller's line.
  out.end += static_cast<std::size_t>(line.data() - raw_line.data());

  const std::string_view addr = out.fields[0];
  if (addr.size() < 2 || addr.size() > 10)
    return Reject::kBadAddress;
  for (char c : addr)
    if (!isAlnum(c))
      return Reject::kBadAddress;
  if (addr[0] == 'P') {
    out.talker = addr.substr(0, 1);
    out.type = addr.substr(1);
  } else {
    if (addr.size() < 3)
      return Reject::kBadAddress;
    out.talker = addr.substr(0, 2);
    out.type = addr.substr(2);
  }
  return Reject::kNone;
}

std::size_t findSentenceStart(std::string_view line, std::size_t from) {
  for (std::size_t i = from; i < line.size(); ++i) {
    const char c = line[i];
    if (c != '$' && c != '!')
      continue;
    if (i > from && line[i - 1] == '\\' && i >= 2) {
      // A tag block ends right here: back up to its opening backslash if it is in range.
      std::size_t open = line.rfind('\\', i - 2);
      if (open != std::string_view::npos && open >= from)
        return open;
    }
    return i;
  }
  return std::string_view::npos;
}

std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t'))
    ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t'))
    --e;
  return s.substr(b, e - b);
}

bool parseDouble(std::string_view field, double& value) {
  field = trim(field);
  if (!field.empty() && field[0] == '+')
    field.remove_prefix(1);
  if (field.empty())
    return false;
  double v;
  auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (r.ec != std::errc() || r.ptr != field.data() + field.size())
    return false;
  value = v;
  return true;
}

bool parseInt(std::string_view field, long& value) {
  field = trim(field);
  if (!field.empty() && field[0] == '+')
    field.remove_prefix(1);
  if (field.empty())
    return false;
  long v;
  auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (r.ec != std::errc() || r.ptr != field.data() + field.size())
    return false;
  value = v;
  return true;
}

char letter(std::string_view field) {
  field = trim(field);
  return field.empty() ? '\0' : field[0];
}

bool parseLatLon(std::string_view value, std::string_view hemi, bool is_lat, double& out) {
  double v;
  if (!parseDouble(value, v) || !std::isfinite(v) || v < 0.0)  // "nan"/"inf" parse: reject them
    return false;
  const double deg = std::floor(v / 100.0);
  const double min = v - deg * 100.0;
  if (min >= 60.0)
    return false;
  double d = deg + min / 60.0;
  const char h = letter(hemi);
  if (is_lat) {
    if (h == 'S')
      d = -d;
    else if (h != 'N')
      return false;
    if (std::fabs(d) > 90.0)
      return false;
  } else {
    if (h == 'W')
      d = -d;
    else if (h != 'E')
      return false;
    if (std::fabs(d) > 180.0)
      return false;
  }
  out = d;
  return true;
}

}  // namespace nmea
}  // namespace asv
