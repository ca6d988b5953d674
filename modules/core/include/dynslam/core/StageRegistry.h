#pragma once
// Creates stages by class name, so a new detector or estimator is one class plus one ini line.
#include <dynslam/core/Stage.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dynslam::core {

class StageRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Stage>()>;

  /// Registers `factory` under `className`; registering a name twice is a programming error
  /// (std::logic_error).
  void add(const std::string& className, Factory factory);

  template <class StageT>
  void add(const std::string& className) {
    add(className, [] { return std::make_unique<StageT>(); });
  }

  /// Throws ConfigError naming `className` and listing the known names when it is unknown.
  std::unique_ptr<Stage> create(const std::string& className) const;

  bool contains(const std::string& className) const;
  std::vector<std::string> classNames() const;

 private:
  std::map<std::string, Factory> factories_;
};

}  // namespace dynslam::core
