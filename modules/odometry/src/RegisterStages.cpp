#include "dynslam/odometry/RegisterStages.h"

#include "dynslam/odometry/RgbdOdometryStage.h"

#include <dynslam/core/StageRegistry.h>

namespace dynslam::odometry {

void registerStages(core::StageRegistry& registry) {
  registry.add<RgbdOdometryStage>("RgbdOdometry");
}

}  // namespace dynslam::odometry
