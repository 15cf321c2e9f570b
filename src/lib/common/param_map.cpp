#include "asv_core/common/param_map.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace asv {

namespace {

const char* typeName(ParamType t) {
  switch (t) {
    case ParamType::Bool:
      return "a boolean";
    case ParamType::Int:
      return "an integer";
    case ParamType::Double:
      return "a number";
    case ParamType::String:
      return "a string";
    case ParamType::List:
      return "a list";
    case ParamType::Text:
      break;
  }
  return "text";
}

}  // namespace

void ParamMap::fail(const std::string& message) const {
  read_failed_ = true;
  throw std::invalid_argument(message);
}

void ParamMap::set(const std::string& key, const std::string& value, ParamType type) {
  values_[key] = value;
  lists_.erase(key);
  if (type == ParamType::Text)
    types_.erase(key);
  else
    types_[key] = type;
}

void ParamMap::set(const std::string& key, double value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  set(key, s.str());
}

void ParamMap::setList(const std::string& key, const std::vector<std::string>& items) {
  std::string text = "[";
  for (const auto& i : items)
    text += (text.size() > 1 ? ", " : "") + i;
  set(key, text + "]", ParamType::List);
  lists_[key] = items;
}

void ParamMap::merge(const ParamMap& other) {
  for (const auto& kv : other.values_) {
    auto t = other.types_.find(kv.first);
    set(kv.first, kv.second, t == other.types_.end() ? ParamType::Text : t->second);
    auto l = other.lists_.find(kv.first);
    if (l != other.lists_.end())
      lists_[kv.first] = l->second;
  }
}

const std::string* ParamMap::find(const std::string& key, std::initializer_list<ParamType> accepted,
                                  const char* expected) const {
  used_.insert(key);
  auto it = values_.find(key);
  if (it == values_.end())
    return nullptr;
  auto t = types_.find(key);
  const ParamType type = t == types_.end() ? ParamType::Text : t->second;
  if (type == ParamType::Text)  // parsed by the getter (a list getter refuses it)
    return &it->second;
  for (ParamType a : accepted)
    if (a == type)
      return &it->second;
  fail("parameter '" + fullName(key) + "' has the wrong type: " + typeName(type) + " ('" + it->second +
       "') where " + expected + " belongs");
}

double ParamMap::getDouble(const std::string& key, double def) const {
  const std::string* s = find(key, {ParamType::Double, ParamType::Int}, "a number");
  if (!s)
    return def;
  const char* b = s->c_str();
  char* e = nullptr;
  errno = 0;
  const double v = std::strtod(b, &e);
  while (e && (*e == ' ' || *e == '\t'))
    ++e;
  if (e == b || *e != '\0' || errno == ERANGE || !std::isfinite(v))
    fail("parameter '" + fullName(key) + "': '" + *s + "' is not a finite number");
  return v;
}

int ParamMap::getInt(const std::string& key, int def) const {
  const std::string* s = find(key, {ParamType::Int}, "an integer");
  if (!s)
    return def;
  const double v = getDouble(key, def);
  if (v != std::floor(v) || std::fabs(v) > 2e9)
    fail("parameter '" + fullName(key) + "': '" + *s + "' is not an integer");
  return static_cast<int>(v);
}

std::size_t ParamMap::getSize(const std::string& key, std::size_t def, std::size_t min) const {
  if (!has(key)) {
    used_.insert(key);
    return def;
  }
  const int v = getInt(key, 0);
  if (v < 0 || static_cast<std::size_t>(v) < min)
    fail("parameter '" + fullName(key) + "' must be >= " + std::to_string(min));
  return static_cast<std::size_t>(v);
}

bool ParamMap::getBool(const std::string& key, bool def) const {
  const std::string* s = find(key, {ParamType::Bool}, "a boolean");
  if (!s)
    return def;
  if (*s == "true" || *s == "True" || *s == "1" || *s == "yes")
    return true;
  if (*s == "false" || *s == "False" || *s == "0" || *s == "no")
    return false;
  fail("parameter '" + fullName(key) + "': '" + *s + "' is not a boolean");
}

std::string ParamMap::getString(const std::string& key, const std::string& def) const {
  const std::string* s = find(key, {ParamType::String}, "a string");
  return s ? *s : def;
}

std::vector<std::string> ParamMap::getStringList(const std::string& key,
                                                 const std::vector<std::string>& def) const {
  const std::string* s = find(key, {ParamType::List}, "a list of strings");
  if (!s)
    return def;
  auto l = lists_.find(key);
  if (l == lists_.end())
    fail("parameter '" + fullName(key) + "': '" + *s + "' is not a list of strings");
  return l->second;
}

std::vector<std::string> ParamMap::unknownKeys(const std::vector<std::string>& skip) const {
  std::vector<std::string> out;
  for (const auto& kv : values_) {
    bool skipped = false;
    for (const auto& s : skip)
      skipped = skipped || kv.first.compare(0, s.size(), s) == 0;
    if (!skipped && !used_.count(kv.first))
      out.push_back(kv.first);
  }
  return out;
}

void ParamMap::rejectUnknown(const std::string& context) const {
  const auto unknown = unknownKeys();
  if (unknown.empty())
    return;
  std::string msg = context + ": unknown parameter(s):";
  for (const auto& k : unknown)
    msg += " '" + fullName(k) + "'";
  throw std::invalid_argument(msg);
}

ParamMap ParamMap::sub(const std::string& prefix) const {
  ParamMap out;
  out.label_ = label_ + prefix + "/";
  const std::string p = prefix + "/";
  for (const auto& kv : values_) {
    if (kv.first.compare(0, p.size(), p) != 0)
      continue;
    const std::string k = kv.first.substr(p.size());
    out.values_[k] = kv.second;
    auto t = types_.find(kv.first);
    if (t != types_.end())
      out.types_[k] = t->second;
    auto l = lists_.find(kv.first);
    if (l != lists_.end())
      out.lists_[k] = l->second;
  }
  return out;
}

}  // namespace asv
