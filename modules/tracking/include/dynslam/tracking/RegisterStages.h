#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::tracking {
/// Adds Tracking (TrackingStage).
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::tracking
