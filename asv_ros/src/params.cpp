#include "asv_ros/params.h"

namespace asv_ros {

void checkUnknownParams(const ros::NodeHandle& nh, const std::set<std::string>& known,
                        const std::string& yaml, const std::vector<std::string>& subtrees) {
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names))
    throw std::runtime_error("cannot list the parameter server's names (is the master running?)");
  const std::string prefix = nh.getNamespace() + "/";
  for (const std::string& n : names) {
    if (n.compare(0, prefix.size(), prefix) != 0)
      continue;
    const std::string key = n.substr(prefix.size());
    bool in_subtree = false;
    for (const auto& s : subtrees)
      in_subtree = in_subtree || key.compare(0, s.size(), s) == 0;
    if (!in_subtree && !known.count(key))
      throw std::invalid_argument("unknown parameter '" + n + "' (typo? see " + yaml + " for the keys)");
  }
}

void getParam(const ros::NodeHandle& nh, const std::string& key, std::size_t& value, std::size_t min) {
  if (!nh.hasParam(key))
    return;
  int v = 0;
  if (!nh.getParam(key, v))
    throw std::invalid_argument("parameter '" + nh.resolveName(key) + "' must be an integer");
  if (v < 0 || static_cast<std::size_t>(v) < min)
    throw std::invalid_argument("parameter '" + nh.resolveName(key) + "' must be >= " + std::to_string(min));
  value = static_cast<std::size_t>(v);
}

}  // namespace asv_ros
