#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::estimator {
/// Adds Estimator (EstimatorStage).
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::estimator
