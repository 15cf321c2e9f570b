// The one strict parameter reader of the stack's nodes. A node reads its private namespace into an
// asv::ParamMap that keeps each value's type, builds its Config struct from it with the core's
// fromParams() (the same code the batch runner and the tests use), and rejects what no fromParams()
// read. A typo in a launch file or YAML, or a value of the wrong type, stops the node with a message
// naming the parameter, instead of letting it run silently on a default.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <asv_core/common/param_map.h>
#include <ros/ros.h>

namespace asv_ros {

// Every parameter under the namespace of `nh`, nested keys as "exchange/topic", each with the type the
// parameter server holds, labelled with the namespace for messages. A list of anything but scalars is
// std::invalid_argument naming it. Empty when the namespace holds nothing.
asv::ParamMap readParams(const ros::NodeHandle& nh);

// Throws std::invalid_argument naming the first key of `params` that no getter read and that is not
// under one of `subtrees` ("evaluation/": a subtree another reader checks). `yaml` is the file that
// documents the keys, for the message.
void rejectUnknown(const asv::ParamMap& params, const std::string& yaml,
                   const std::vector<std::string>& subtrees = {});

// For a fromParams() that failed: when every key was read (a value missing or out of range, not one of
// the wrong type), an unknown key is the likelier cause, and is named instead (rejectUnknown).
void rejectTypoBehindError(const asv::ParamMap& params, const std::string& yaml,
                           const std::vector<std::string>& subtrees = {});

// A node's Config struct (a core type with a static fromParams(const asv::ParamMap&) that reads and
// validates its keys) from the private namespace `pnh`; then rejectUnknown(). The one way a node
// loads its parameters.
template <typename Config>
Config loadConfig(const ros::NodeHandle& pnh, const std::string& yaml,
                  const std::vector<std::string>& subtrees = {}) {
  const asv::ParamMap params = readParams(pnh);
  try {
    Config config = Config::fromParams(params);
    rejectUnknown(params, yaml, subtrees);
    return config;
  } catch (const std::invalid_argument&) {
    rejectTypoBehindError(params, yaml, subtrees);
    throw;
  }
}

// A global parameter (`/lockstep`) read into `value` when it is set, keeping `value` (the default)
// otherwise. A value of the wrong type is std::invalid_argument. An integer is accepted for a double
// (roscpp converts it), not for a bool or a string.
template <typename T>
void getParam(const ros::NodeHandle& nh, const std::string& key, T& value) {
  if (nh.hasParam(key) && !nh.getParam(key, value))
    throw std::invalid_argument("parameter '" + nh.resolveName(key) + "' has the wrong type");
}

}  // namespace asv_ros
