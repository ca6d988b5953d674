#include "dynslam/frontend/RegisterStages.h"

#include "dynslam/frontend/DynamicClassificationStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::frontend {

void registerStages(core::StageRegistry& registry) {
  registry.add<DynamicClassificationStage>("DynamicClassification");
}

}  // namespace dynslam::frontend
