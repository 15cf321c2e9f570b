// A minimal ordered JSON tree and its writer, shared by the run result (result_json.cpp) and the
// GeoJSON of a run (geojson.cpp): keys in insertion order, numbers at a fixed precision each, NaN and
// inf as null, so that the same run gives the same bytes. Private to the eval stage.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace asv::json_tree {

// Precisions: metres and seconds 0.1, degrees 0.1, ratios and scores 1e-4, milliseconds 1e-3,
// latitude/longitude 1e-7 deg (1 cm).
constexpr int kMetres = 1, kSeconds = 1, kDegrees = 1, kRatio = 4, kMs = 3, kLatLon = 7;

struct Json {
  enum Kind { Null, Bool, Num, Int, Str, Arr, Obj } kind = Null;
  double num = 0.0;
  int prec = 3;
  long long i = 0;
  bool b = false;
  std::string s;
  std::vector<std::pair<std::string, Json>> obj;
  std::vector<Json> arr;

  static Json number(double v, int prec) {
    Json j;
    if (!std::isfinite(v))
      return j;  // null: NaN and inf are never printed
    j.kind = Num;
    j.num = v;
    j.prec = prec;
    return j;
  }
  static Json integer(long long v) {
    Json j;
    j.kind = Int;
    j.i = v;
    return j;
  }
  static Json boolean(bool v) {
    Json j;
    j.kind = Bool;
    j.b = v;
    return j;
  }
  static Json string(const std::string& v) {
    Json j;
    j.kind = Str;
    j.s = v;
    return j;
  }
  static Json object() {
    Json j;
    j.kind = Obj;
    return j;
  }
  static Json array() {
    Json j;
    j.kind = Arr;
    return j;
  }
  Json& add(const std::string& key, Json v) {
    obj.emplace_back(key, std::move(v));
    return *this;
  }
};

// `s` as a JSON string literal, escaped.
std::string quote(const std::string& s);
// `v` with `prec` decimals, without trailing zeros.
std::string numberText(double v, int prec);
// Appends `j` to `out`: one line, or indented by two spaces a level from `indent` when `pretty`.
void write(const Json& j, bool pretty, int indent, std::string& out);

}  // namespace asv::json_tree
