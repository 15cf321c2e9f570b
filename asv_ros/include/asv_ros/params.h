// The one strict parameter reader of the stack's nodes: a typo in a launch file or YAML, or a value of
// the wrong type, stops the node with a message naming the parameter, instead of letting it run
// silently on a default.
#pragma once

#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>

namespace asv_ros {

// Throws std::invalid_argument naming the first parameter under the namespace of `nh` that is not in
// `known` (keys relative to that namespace, nested ones as "exchange/topic") and not under one of
// `subtrees` ("evaluation/": a subtree another reader checks). `yaml` is the file that documents the
// keys, for the message.
void checkUnknownParams(const ros::NodeHandle& nh, const std::set<std::string>& known,
                        const std::string& yaml, const std::vector<std::string>& subtrees = {});

// Reads `key` into `value` when it is set, keeping `value` (the default) otherwise. A value of the
// wrong type is std::invalid_argument. An integer is accepted for a double (roscpp converts it), not
// for a bool or a string.
template <typename T>
void getParam(const ros::NodeHandle& nh, const std::string& key, T& value) {
  if (nh.hasParam(key) && !nh.getParam(key, value))
    throw std::invalid_argument("parameter '" + nh.resolveName(key) + "' has the wrong type");
}

// Same for unsigned sizes and ports, read as int and checked to be >= `min`.
void getParam(const ros::NodeHandle& nh, const std::string& key, std::size_t& value, std::size_t min = 0);

}  // namespace asv_ros
