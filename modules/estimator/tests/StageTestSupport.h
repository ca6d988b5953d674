#pragma once
// An EstimatorStage configured from a few [Estimator] lines, for the stage's tests.
#include <dynslam/core/Config.h>
#include <dynslam/estimator/EstimatorStage.h>

#include <memory>
#include <string>

namespace dynslam::estimator::testing {

/// A stage whose solves stop at their iteration limit, not on the clock (repeatable runs).
inline std::unique_ptr<EstimatorStage> makeStage(const std::string& settings = "") {
  auto stage = std::make_unique<EstimatorStage>();
  stage->configure(core::IniConfig::fromText("[Estimator]\nmax_solver_time = 100\n" + settings),
                   "Estimator");
  return stage;
}

/// Why configuring a stage with `settings` is refused (the ConfigError's text), "" when it is not.
inline std::string configRefusal(const std::string& settings) {
  try {
    makeStage(settings);
  } catch (const core::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dynslam::estimator::testing
