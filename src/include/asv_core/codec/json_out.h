// Buffered JSON text output with hand-written number formatting, for the decoders' JSON tools
// (`asv_ais_decode`): printf per field costs more than the decoding itself.
//
// The caller reserves room before each record (reserveRecord) and flushes the buffer to its sink;
// the writers do not check the capacity field by field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

namespace asv {
namespace json {

class Out {
public:
  // Room guaranteed for one record: the longest AIS object (a 1008-bit binary message with arrays)
  // stays far below this.
  static constexpr std::size_t kRecordRoom = 16384;

  explicit Out(std::FILE* sink = stdout, std::size_t capacity = std::size_t{1} << 20)
      : sink_(sink), buf_(capacity) {}
  ~Out() { flush(); }
  Out(const Out&) = delete;
  Out& operator=(const Out&) = delete;

  // Writes the buffer to the sink (or keeps it when the sink is null: see text()).
  void flush() {
    if (sink_ && n_ > 0)
      std::fwrite(buf_.data(), 1, n_, sink_);
    if (sink_)
      n_ = 0;
  }
  // Called before each record; `extra` is room for caller-sized strings (a device name).
  void reserveRecord(std::size_t extra) {
    if (n_ + kRecordRoom + extra > buf_.size())
      flush();
    if (n_ + kRecordRoom + extra > buf_.size())
      buf_.resize(n_ + kRecordRoom + extra);
  }
  // What was written since the last flush (the whole output for a null sink).
  std::string_view text() const { return std::string_view(buf_.data(), n_); }
  void clear() { n_ = 0; }

  template <std::size_t N>
  void lit(const char (&s)[N]) {
    std::memcpy(buf_.data() + n_, s, N - 1);
    n_ += N - 1;
  }
  void raw(std::string_view s) {
    std::memcpy(buf_.data() + n_, s.data(), s.size());
    n_ += s.size();
  }
  void ch(char c) { buf_[n_++] = c; }
  void u(std::uint64_t v) { pad(v, 1); }
  void i(std::int64_t v) {
    if (v < 0) {
      buf_[n_++] = '-';
      u(static_cast<std::uint64_t>(-(v + 1)) + 1);
    } else {
      u(static_cast<std::uint64_t>(v));
    }
  }
  // Zero-padded to `width` digits (%02u, %04u).
  void pad(std::uint64_t v, int width) {
    char tmp[24];
    int k = 0;
    do {
      tmp[k++] = static_cast<char>('0' + v % 10);
      v /= 10;
    } while (v);
    while (k < width)
      tmp[k++] = '0';
    while (k)
      buf_[n_++] = tmp[--k];
  }
  void b(bool v) {
    if (v)
      lit("true");
    else
      lit("false");
  }
  // Quoted JSON string, escaped as gpsd's json_stringify does.
  void str(std::string_view s) {
    buf_[n_++] = '"';
    for (char c : s) {
      const unsigned char uc = static_cast<unsigned char>(c);
      if (uc < 0x20 || uc > 0x7e) {
        n_ += static_cast<std::size_t>(std::snprintf(buf_.data() + n_, 8, "\\u%04x", uc));
      } else {
        if (c == '"' || c == '\\')
          buf_[n_++] = '\\';
        buf_[n_++] = c;
      }
    }
    buf_[n_++] = '"';
  }
  // v / 10 with one decimal (%.1f of an exact tenth).
  void tenths(std::uint64_t v) {
    u(v / 10);
    buf_[n_++] = '.';
    buf_[n_++] = static_cast<char>('0' + v % 10);
  }
  // raw / 600000 with six decimals, as %.6f: raw * 5 / 3 rounded, never a tie, so integer
  // arithmetic gives printf's digits exactly.
  void latlon(std::int32_t raw) {
    std::int64_t x = static_cast<std::int64_t>(raw) * 5;
    const bool neg = x < 0;
    std::uint64_t q = (static_cast<std::uint64_t>(neg ? -x : x) + 1) / 3;
    if (neg && q != 0)
      buf_[n_++] = '-';
    u(q / 1000000);
    buf_[n_++] = '.';
    pad(q % 1000000, 6);
  }
  // printf of one double (`fmt` holds one conversion, e.g. "%.1f").
  void printf1(const char* fmt, double v) {
    n_ += static_cast<std::size_t>(std::snprintf(buf_.data() + n_, 64, fmt, v));
  }

private:
  std::FILE* sink_;
  std::vector<char> buf_;
  std::size_t n_ = 0;
};

}  // namespace json
}  // namespace asv
