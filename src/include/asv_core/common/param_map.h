// A flat key/value configuration tree ("aco/ants" style keys), filled from rosparam in ROS nodes and
// from YAML in the batch runner, so that one plugin configures the same way in both.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace asv {

class ParamMap {
public:
  ParamMap() = default;
  explicit ParamMap(std::map<std::string, std::string> values) : values_(std::move(values)) {}

  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  void set(const std::string& key, double value);
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  const std::map<std::string, std::string>& values() const { return values_; }

  // Typed getters: return the default when the key is absent; throw std::invalid_argument naming the
  // key when the value does not parse. Every key read is remembered (see unknownKeys()).
  double getDouble(const std::string& key, double def) const;
  int getInt(const std::string& key, int def) const;
  bool getBool(const std::string& key, bool def) const;
  std::string getString(const std::string& key, const std::string& def) const;

  // Keys present but never read: typos in a parameter file. Call after configuring.
  std::vector<std::string> unknownKeys() const;
  // Throws std::invalid_argument listing the unknown keys, if any, prefixed with `context`.
  void rejectUnknown(const std::string& context) const;

  // A copy holding only the keys under `prefix/`, with the prefix removed.
  ParamMap sub(const std::string& prefix) const;

private:
  std::map<std::string, std::string> values_;
  mutable std::set<std::string> used_;
};

}  // namespace asv
