#include "asv_planning/plugin_loader.h"

#include <stdexcept>

namespace asv_planning {

namespace {
constexpr const char* kOwnPrefix = "asv_planning/";
}  // namespace

PluginLoader::PluginLoader() : loader_("asv_planning", "asv::PlannerAlgorithm") {}

std::string PluginLoader::fullName(const std::string& name) {
  return name.find('/') == std::string::npos ? kOwnPrefix + name : name;
}

std::string PluginLoader::parameterName(const std::string& name) {
  const std::string full = fullName(name);
  return full.rfind(kOwnPrefix, 0) == 0 ? full.substr(std::string(kOwnPrefix).size()) : full;
}

std::vector<std::string> PluginLoader::declared() const {
  return const_cast<pluginlib::ClassLoader<asv::PlannerAlgorithm>&>(loader_).getDeclaredClasses();
}

std::vector<std::string> PluginLoader::parameterNames() const {
  std::vector<std::string> names;
  for (const auto& d : declared())
    names.push_back(parameterName(d));
  return names;
}

pluginlib::UniquePtr<asv::PlannerAlgorithm> PluginLoader::load(const std::string& name,
                                                               const asv::ParamMap& config) {
  const std::string full = fullName(name);
  pluginlib::UniquePtr<asv::PlannerAlgorithm> planner;
  try {
    planner = loader_.createUniqueInstance(full);
  } catch (const pluginlib::PluginlibException& e) {
    std::string list;
    for (const auto& d : declared())
      list += (list.empty() ? "" : ", ") + d;
    throw std::runtime_error("cannot load planner '" + name + "' (" + e.what() +
                             "); declared planners: " + list);
  }
  planner->initialize(config);
  return planner;
}

}  // namespace asv_planning
