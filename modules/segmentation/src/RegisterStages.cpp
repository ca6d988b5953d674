#include "dynslam/segmentation/RegisterStages.h"

#include "dynslam/segmentation/FloorRemovalStage.h"
#include "dynslam/segmentation/SegmentationStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::segmentation {

void registerStages(core::StageRegistry& registry) {
  registry.add<SegmentationStage>("Segmentation");
  registry.add<FloorRemovalStage>("FloorRemoval");
}

}  // namespace dynslam::segmentation
