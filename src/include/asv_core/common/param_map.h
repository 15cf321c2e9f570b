// A flat key/value configuration tree ("aco/ants" style keys), filled from rosparam in ROS nodes and
// from YAML in the batch runner, so that one plugin (and one node's Config struct) configures the same
// way in both.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace asv {

// How a value was given. Text (a YAML scalar of the batch runner) parses as whatever the getter asks
// for. The others are the types a typed source (the ROS parameter server) gave; a getter of another
// type refuses them as roscpp's getParam does: an integer is a valid double, but 1 is not a boolean
// and 5 is not a string or a list.
enum class ParamType { Text, Bool, Int, Double, String, List };

class ParamMap {
public:
  ParamMap() = default;
  explicit ParamMap(std::map<std::string, std::string> values) : values_(std::move(values)) {}

  void set(const std::string& key, const std::string& value, ParamType type = ParamType::Text);
  void set(const std::string& key, double value);
  void setList(const std::string& key, const std::vector<std::string>& items);
  // Every key of `other` (its value and type), replacing this map's.
  void merge(const ParamMap& other);
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  const std::map<std::string, std::string>& values() const { return values_; }
  // Prefix of the keys in error messages: a node's namespace ("/sim/"), so that a message names the
  // parameter as the user wrote it.
  void setLabel(const std::string& label) { label_ = label; }
  std::string fullName(const std::string& key) const { return label_ + key; }

  // Typed getters: return the default when the key is absent; throw std::invalid_argument naming the
  // key when the value does not parse or has the wrong type. Every key read is remembered (see
  // unknownKeys()).
  double getDouble(const std::string& key, double def) const;
  int getInt(const std::string& key, int def) const;
  bool getBool(const std::string& key, bool def) const;
  std::string getString(const std::string& key, const std::string& def) const;
  std::vector<std::string> getStringList(const std::string& key, const std::vector<std::string>& def) const;
  // An unsigned count or size, at least `min`.
  std::size_t getSize(const std::string& key, std::size_t def, std::size_t min = 0) const;

  // Keys present but never read, outside the `skip` subtrees ("evaluation/": a subtree another reader
  // owns): typos in a parameter file. Call after configuring.
  std::vector<std::string> unknownKeys(const std::vector<std::string>& skip = {}) const;
  // Throws std::invalid_argument listing the unknown keys, if any, prefixed with `context`.
  void rejectUnknown(const std::string& context) const;

  // Whether a getter has refused a value (wrong type, no parse): then keys after it were not read,
  // and unknownKeys() also holds valid ones.
  bool readFailed() const { return read_failed_; }

  // A copy holding only the keys under `prefix/`, with the prefix removed (types kept, label extended).
  ParamMap sub(const std::string& prefix) const;

private:
  [[noreturn]] void fail(const std::string& message) const;  // std::invalid_argument, readFailed()
  // The value of `key` when present (marked used), after checking its type is one of `accepted`.
  const std::string* find(const std::string& key, std::initializer_list<ParamType> accepted,
                          const char* expected) const;

  std::map<std::string, std::string> values_;
  std::map<std::string, ParamType> types_;  // absent: Text
  std::map<std::string, std::vector<std::string>> lists_;
  std::string label_;
  mutable std::set<std::string> used_;
  mutable bool read_failed_ = false;
};

}  // namespace asv
