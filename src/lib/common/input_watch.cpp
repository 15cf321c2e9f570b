#include "asv_core/common/input_watch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace asv {

void InputWatchConfig::validate() const {
  if (!(input_timeout > 0.0) || !std::isfinite(input_timeout))
    throw std::invalid_argument("watch/input_timeout must be > 0 s");
  if (!(startup_grace >= 0.0) || !std::isfinite(startup_grace))
    throw std::invalid_argument("watch/startup_grace must be >= 0 s");
  if (!(wall_floor >= 0.0) || !std::isfinite(wall_floor))
    throw std::invalid_argument("watch/wall_floor must be >= 0 s");
}

InputWatchConfig InputWatchConfig::fromParams(const ParamMap& p, const InputWatchConfig& defaults) {
  InputWatchConfig c = defaults;
  c.input_timeout = p.getDouble("watch/input_timeout", c.input_timeout);
  c.startup_grace = p.getDouble("watch/startup_grace", c.startup_grace);
  c.wall_floor = p.getDouble("watch/wall_floor", c.wall_floor);
  c.validate();
  return c;
}

InputWatch::InputWatch(const InputWatchConfig& config) : cfg_(config) {
  cfg_.validate();
}

void InputWatch::add(const std::string& name, double timeout) {
  if (!(timeout > 0.0) || !std::isfinite(timeout))
    throw std::invalid_argument("input watch: timeout of '" + name + "' must be > 0 s");
  if (!inputs_.emplace(name, Input{timeout}).second)
    throw std::invalid_argument("input watch: input '" + name + "' added twice");
  order_.push_back(name);
}

InputWatch::Input& InputWatch::find(const std::string& name) {
  auto it = inputs_.find(name);
  if (it == inputs_.end())
    throw std::invalid_argument("input watch: unknown input '" + name + "'");
  return it->second;
}

void InputWatch::received(const std::string& name, double now, double wall) {
  Input& in = find(name);
  in.last = now;
  in.last_wall = wall;
  in.seen = true;
}

void InputWatch::busy(double now, double wall) {
  busy_ = now;
  busy_wall_ = wall;
}

void InputWatch::start(double now, double wall) {
  started_ = true;
  start_ = now;
  start_wall_ = wall;
}

std::vector<StaleInput> InputWatch::stale(double now, double wall) {
  if (!started_)
    start(now, wall);
  std::vector<StaleInput> out;
  for (const std::string& name : order_) {
    const Input& in = inputs_.at(name);
    // Since the last message, or since the start with the start-up grace; either way at least a
    // timeout since the node was last busy (it has not read its queue yet). The grace does not move
    // with `busy`: a node that replans often still reports an input that never came.
    const double last = in.seen ? in.last : start_ + cfg_.startup_grace;
    const double last_wall = in.seen ? in.last_wall : start_wall_ + cfg_.startup_grace;
    if (now - std::max(last, busy_) <= in.timeout ||
        wall - std::max(last_wall, busy_wall_) <= cfg_.wall_floor)
      continue;
    char line[256];
    if (in.seen)
      std::snprintf(line, sizeof line, "%s: none for %.1f s (timeout %.1f s)", name.c_str(), now - in.last,
                    in.timeout);
    else
      std::snprintf(line, sizeof line, "%s: nothing received in %.1f s since start", name.c_str(),
                    now - start_);
    out.push_back({name, line});
  }
  return out;
}

double InputWatch::age(const std::string& name, double now) const {
  auto it = inputs_.find(name);
  if (it == inputs_.end())
    throw std::invalid_argument("input watch: unknown input '" + name + "'");
  if (!started_)
    return -1.0;
  return now - (it->second.seen ? it->second.last : start_);
}

bool InputWatch::everReceived(const std::string& name) const {
  auto it = inputs_.find(name);
  return it != inputs_.end() && it->second.seen;
}

void InputWatch::reset() {
  for (auto& [name, in] : inputs_)
    in = Input{in.timeout};
  started_ = false;
  busy_ = busy_wall_ = -1e300;
}

}  // namespace asv
