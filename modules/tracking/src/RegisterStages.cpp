#include "dynslam/tracking/RegisterStages.h"

#include "dynslam/tracking/ObjectStateStage.h"
#include "dynslam/tracking/TrackingStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::tracking {

void registerStages(core::StageRegistry& registry) {
  registry.add<TrackingStage>("Tracking");
  registry.add<ObjectStateStage>("ObjectStates");
}

}  // namespace dynslam::tracking
