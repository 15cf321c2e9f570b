// AIS messages as JSON objects in the format of gpsd 3.22 (`gpsdecode -j`, scaled, and
// `gpsdecode -u -j`, unscaled): the same keys, in the same order, with the same number formats, so
// that tools written for gpsd read our output unchanged.
//
// Types 1-5, 18, 19, 21, 24 and 27 are printed from their decoded Message by asv_ais_decode; every
// other type (6-17, 20, 22, 23, 25, 26), and the binary payloads of types 6 and 8 with the
// DAC/FID sub-types gpsd 3.22 decodes, is printed here field by field from the payload bits. A
// sub-type gpsd does not decode, or one whose length does not fit its layout, is printed as gpsd
// does: the raw bits as "data":"<bit count>:<hex>".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/json_out.h"

namespace asv {
namespace ais {

// Writes the `,"name":value` members of one JSON object (or array element) in order.
class AisFields {
public:
  AisFields(json::Out& out, bool scaled) : o_(out), scaled_(scaled) {}
  bool scaled() const { return scaled_; }
  json::Out& out() { return o_; }

  void u(const char* name, std::uint64_t v) {
    key(name);
    o_.u(v);
  }
  void i(const char* name, std::int64_t v) {
    key(name);
    o_.i(v);
  }
  void b(const char* name, bool v) {
    key(name);
    o_.b(v);
  }
  void str(const char* name, std::string_view v) {
    key(name);
    o_.str(v);
  }
  // printf("%.<decimals>f", v).
  void f(const char* name, double v, int decimals);
  // Unscaled: the raw integer; scaled: raw / divisor with `decimals` decimals (gpsd divides; a
  // multiplication by the inverse rounds differently at the ties).
  void scaledDiv(const char* name, std::int64_t raw, double divisor, int decimals) {
    if (scaled_)
      f(name, static_cast<double>(raw) / divisor, decimals);
    else
      i(name, raw);
  }
  // Unscaled: the raw integer; scaled: raw * factor + offset with `decimals` decimals.
  void scaledNum(const char* name, std::int64_t raw, double factor, int decimals, double offset = 0.0) {
    if (scaled_)
      f(name, static_cast<double>(raw) * factor + offset, decimals);
    else
      i(name, raw);
  }
  // A value with its legend: "name":v,"name_text":"legend" in both forms.
  void withText(const char* name, unsigned v, std::string_view name_text, const char* legend) {
    u(name, v);
    key(name_text);
    o_.ch('"');
    o_.raw(legend);
    o_.ch('"');
  }
  // Unscaled: the number; scaled: the legend as a string in its place.
  void legendOrNumber(const char* name, unsigned v, const char* legend) {
    if (scaled_)
      str(name, legend);
    else
      u(name, v);
  }
  // Six-bit text of `nchars` characters at `start`, as gpsd reads a fixed-size text field: read like
  // every field, past the payload end too (the fill bits, then zeros, which read as the '@' that ends
  // the text), stopping at the first '@', trailing spaces trimmed.
  void text6(const char* name, const Payload& p, std::size_t start, std::size_t nchars);
  // The six-bit text from `start` to the payload end.
  void text6ToEnd(const char* name, const Payload& p, std::size_t start) {
    text6(name, p, start, p.bits() > start ? (p.bits() - start) / 6 : 0);
  }
  // The bits from `start` to the payload end as gpsd prints binary data: "<count>:<hex>", the
  // last byte padded with zero bits.
  void data(const char* name, const Payload& p, std::size_t start);
  // `count` bits from `start`, bits at or after `limit` (when not 0) printed as 0.
  void dataBits(const char* name, const Payload& p, std::size_t start, std::size_t count, std::size_t limit);
  // "MM-DDTHH:MMZ", or "DDTHH:MMZ" without `with_month` (month then ignored).
  void stamp(const char* name, unsigned month, unsigned day, unsigned hour, unsigned minute,
             bool with_month = true);
  // The digits of a stamp alone: "MM-DDTHH:MM" or "DDTHH:MM" (zero-padded, no quotes, no zone letter).
  void stampBody(unsigned month, unsigned day, unsigned hour, unsigned minute, bool with_month = true);

  // Nesting: "name":[ {...}, ... ].
  void beginArray(const char* name) {
    key(name);
    o_.ch('[');
    first_ = true;
  }
  void endArray() {
    o_.ch(']');
    first_ = false;
  }
  void beginObject() {
    if (!first_)
      o_.ch(',');
    o_.ch('{');
    first_ = true;
  }
  void endObject() {
    o_.ch('}');
    first_ = false;
  }

  // `,"name":` (no comma for the first member of an object).
  void key(std::string_view name) {
    if (!first_)
      o_.ch(',');
    first_ = false;
    o_.ch('"');
    o_.raw(name);
    o_.lit("\":");
  }

private:
  json::Out& o_;
  bool scaled_;
  bool first_ = false;
};

// The members after "scaled" of a message of type 6-17, 20, 22, 23, 25 or 26 whose payload is `p`
// (Status::kMessage from the decoder). False, writing nothing, for the other types.
bool writePayloadFields(const Payload& p, AisFields& w);

// IMO289 route information, addressed (type 6 DAC 1 FID 28, `base` 88) or broadcast (type 8 DAC 1
// FID 27, `base` 56): linkage, sender, route type with `rtype_text`, start, duration, then as many
// 55-bit waypoints as the 5-bit count says, read past the payload end when it is short (as gpsd does).
void writeRouteInformation(const Payload& p, std::size_t base, const char* rtype_text, AisFields& w);

// Structured DAC/FID sub-types (the members after "fid"; `p` is the whole payload). False, writing
// nothing, when gpsd 3.22 would print the raw data instead.
bool writeType6Application(const Payload& p, unsigned dac, unsigned fid, AisFields& w);
bool writeType8Application(const Payload& p, unsigned dac, unsigned fid, AisFields& w);

}  // namespace ais
}  // namespace asv
