#include "dynslam/detection/RegisterStages.h"

#include "dynslam/detection/DetectionStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::detection {

void registerStages(core::StageRegistry& registry) { registry.add<DetectionStage>("Detection"); }

}  // namespace dynslam::detection
