#include "dynslam/core/StageRegistry.h"

#include <stdexcept>

namespace dynslam::core {

void StageRegistry::add(const std::string& className, Factory factory) {
  if (!factories_.emplace(className, std::move(factory)).second)
    throw std::logic_error("stage class '" + className + "' registered twice");
}

std::unique_ptr<Stage> StageRegistry::create(const std::string& className) const {
  const auto it = factories_.find(className);
  if (it == factories_.end()) {
    std::string known;
    for (const auto& [name, f] : factories_) known += (known.empty() ? "" : ", ") + name;
    throw ConfigError("unknown stage class '" + className +
                      "'; known classes: " + (known.empty() ? "(none)" : known));
  }
  return it->second();
}

bool StageRegistry::contains(const std::string& className) const {
  return factories_.count(className) > 0;
}

std::vector<std::string> StageRegistry::classNames() const {
  std::vector<std::string> names;
  for (const auto& [name, f] : factories_) names.push_back(name);
  return names;
}

}  // namespace dynslam::core
