#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::detection {
/// Adds Detection (DetectionStage).
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::detection
