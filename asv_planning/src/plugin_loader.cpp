#include "asv_planning/plugin_loader.h"

#include <stdexcept>

namespace asv_planning {

PluginLoader::PluginLoader() : loader_("asv_planning", "asv_planning::PlannerPlugin") {}

std::string PluginLoader::fullName(const std::string& name) {
  return name.find('/') == std::string::npos ? "asv_planning/" + name : name;
}

std::vector<std::string> PluginLoader::declared() const {
  return const_cast<pluginlib::ClassLoader<PlannerPlugin>&>(loader_).getDeclaredClasses();
}

pluginlib::UniquePtr<PlannerPlugin> PluginLoader::load(const std::string& name, const asv::ParamMap& config) {
  const std::string full = fullName(name);
  pluginlib::UniquePtr<PlannerPlugin> plugin;
  try {
    plugin = loader_.createUniqueInstance(full);
  } catch (const pluginlib::PluginlibException& e) {
    std::string list;
    for (const auto& d : declared())
      list += (list.empty() ? "" : ", ") + d;
    throw std::runtime_error("cannot load planner '" + name + "' (" + e.what() +
                             "); declared planners: " + list);
  }
  const std::string short_name = full.substr(full.find('/') + 1);
  plugin->initialize(short_name, config);
  return plugin;
}

}  // namespace asv_planning
