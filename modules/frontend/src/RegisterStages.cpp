#include "dynslam/frontend/RegisterStages.h"

#include "dynslam/frontend/DynamicClassificationStage.h"
#include "dynslam/frontend/FeatureTrackingStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::frontend {

void registerStages(core::StageRegistry& registry) {
  registry.add<FeatureTrackingStage>("FeatureTracking");
  registry.add<DynamicClassificationStage>("DynamicClassification");
}

}  // namespace dynslam::frontend
