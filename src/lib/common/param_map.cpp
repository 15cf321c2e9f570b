#include "asv_core/common/param_map.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace asv {

void ParamMap::set(const std::string& key, double value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  values_[key] = s.str();
}

double ParamMap::getDouble(const std::string& key, double def) const {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end())
    return def;
  const char* b = it->second.c_str();
  char* e = nullptr;
  errno = 0;
  const double v = std::strtod(b, &e);
  while (e && (*e == ' ' || *e == '\t'))
    ++e;
  if (e == b || *e != '\0' || errno == ERANGE || !std::isfinite(v))
    throw std::invalid_argument("parameter '" + key + "': '" + it->second + "' is not a finite number");
  return v;
}

int ParamMap::getInt(const std::string& key, int def) const {
  const double v = getDouble(key, def);
  if (v != std::floor(v) || std::fabs(v) > 2e9)
    throw std::invalid_argument("parameter '" + key + "': '" + values_.at(key) + "' is not an integer");
  return static_cast<int>(v);
}

bool ParamMap::getBool(const std::string& key, bool def) const {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end())
    return def;
  const std::string& s = it->second;
  if (s == "true" || s == "True" || s == "1" || s == "yes")
    return true;
  if (s == "false" || s == "False" || s == "0" || s == "no")
    return false;
  throw std::invalid_argument("parameter '" + key + "': '" + s + "' is not a boolean");
}

std::string ParamMap::getString(const std::string& key, const std::string& def) const {
  used_.insert(key);
  auto it = values_.find(key);
  return it == values_.end() ? def : it->second;
}

std::vector<std::string> ParamMap::unknownKeys() const {
  std::vector<std::string> out;
  for (const auto& kv : values_)
    if (!used_.count(kv.first))
      out.push_back(kv.first);
  return out;
}

void ParamMap::rejectUnknown(const std::string& context) const {
  const auto unknown = unknownKeys();
  if (unknown.empty())
    return;
  std::string msg = context + ": unknown parameter(s):";
  for (const auto& k : unknown)
    msg += " '" + k + "'";
  throw std::invalid_argument(msg);
}

ParamMap ParamMap::sub(const std::string& prefix) const {
  ParamMap out;
  const std::string p = prefix + "/";
  for (const auto& kv : values_)
    if (kv.first.compare(0, p.size(), p) == 0)
      out.values_[kv.first.substr(p.size())] = kv.second;
  return out;
}

}  // namespace asv
