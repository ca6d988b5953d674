#include "dynslam/estimator/RegisterStages.h"

#include "dynslam/estimator/EstimatorStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::estimator {

void registerStages(core::StageRegistry& registry) { registry.add<EstimatorStage>("Estimator"); }

}  // namespace dynslam::estimator
