#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::frontend {
/// Adds the front-end stages: DynamicClassification (DynamicClassificationStage) and
/// FeatureTracking (FeatureTrackingStage) as they land.
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::frontend
