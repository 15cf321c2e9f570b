#include "asv_risk/params.h"

#include <vector>

namespace asv_risk {

void checkUnknownParams(const ros::NodeHandle& pnh, const std::set<std::string>& known,
                        const std::string& yaml) {
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names))
    return;
  const std::string prefix = pnh.getNamespace() + "/";
  for (const std::string& n : names) {
    if (n.compare(0, prefix.size(), prefix) != 0)
      continue;
    const std::string key = n.substr(prefix.size());
    if (!known.count(key))
      throw std::invalid_argument("unknown parameter '" + n + "' (typo? see " + yaml + " for the keys)");
  }
}

void getParam(const ros::NodeHandle& pnh, const std::string& key, std::size_t& value, std::size_t min) {
  if (!pnh.hasParam(key))
    return;
  int v = 0;
  if (!pnh.getParam(key, v))
    throw std::invalid_argument("parameter '" + pnh.resolveName(key) + "' must be an integer");
  if (v < 0 || static_cast<std::size_t>(v) < min)
    throw std::invalid_argument("parameter '" + pnh.resolveName(key) + "' must be >= " + std::to_string(min));
  value = static_cast<std::size_t>(v);
}

}  // namespace asv_risk
