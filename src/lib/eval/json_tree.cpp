#include "json_tree.h"

#include <algorithm>
#include <cstdio>

namespace asv::json_tree {

namespace {

bool scalar(const Json& j) {
  return j.kind != Json::Arr && j.kind != Json::Obj;
}

}  // namespace

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

std::string numberText(double v, int prec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  std::string s = buf;
  // "-0.000" is 0: the sign of a zero must not make two equal runs differ.
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos)
    s.erase(0, 1);
  return s;
}

void write(const Json& j, bool pretty, int indent, std::string& out) {
  const std::string pad = pretty ? std::string(2 * (indent + 1), ' ') : "";
  const std::string end_pad = pretty ? std::string(2 * indent, ' ') : "";
  switch (j.kind) {
    case Json::Null:
      out += "null";
      return;
    case Json::Bool:
      out += j.b ? "true" : "false";
      return;
    case Json::Num:
      out += numberText(j.num, j.prec);
      return;
    case Json::Int:
      out += std::to_string(j.i);
      return;
    case Json::Str:
      out += quote(j.s);
      return;
    case Json::Arr: {
      if (j.arr.empty()) {
        out += "[]";
        return;
      }
      const bool flat = !pretty || std::all_of(j.arr.begin(), j.arr.end(), scalar);
      out += "[";
      for (size_t k = 0; k < j.arr.size(); ++k) {
        if (k)
          out += ",";
        if (flat) {
          if (k)
            out += " ";
        } else {
          out += "\n" + pad;
        }
        write(j.arr[k], pretty, indent + 1, out);
      }
      out += flat ? "]" : "\n" + end_pad + "]";
      return;
    }
    case Json::Obj: {
      if (j.obj.empty()) {
        out += "{}";
        return;
      }
      // Inside an array, small objects (manoeuvres) stay on one line even when pretty.
      const bool small = j.obj.size() <= 3 && std::all_of(j.obj.begin(), j.obj.end(),
                                                          [](const auto& kv) { return scalar(kv.second); });
      const bool flat = !pretty || small;
      out += "{";
      for (size_t k = 0; k < j.obj.size(); ++k) {
        if (k)
          out += ",";
        if (flat) {
          if (k)
            out += " ";
        } else {
          out += "\n" + pad;
        }
        out += quote(j.obj[k].first) + ": ";
        write(j.obj[k].second, pretty, indent + 1, out);
      }
      out += flat ? "}" : "\n" + end_pad + "}";
      return;
    }
  }
}

}  // namespace asv::json_tree
