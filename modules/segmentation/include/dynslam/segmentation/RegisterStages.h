#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::segmentation {
/// Adds Segmentation (SegmentationStage, depth-threshold instance segmentation).
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::segmentation
