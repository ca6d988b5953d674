#include <dynslam/system/BuiltinStages.h>

#include <dynslam/core/StageRegistry.h>
#include <dynslam/detection/RegisterStages.h>
#include <dynslam/estimator/RegisterStages.h>
#include <dynslam/frontend/RegisterStages.h>
#include <dynslam/odometry/RegisterStages.h>
#include <dynslam/segmentation/RegisterStages.h>
#include <dynslam/tracking/RegisterStages.h>

namespace dynslam::system {

void registerBuiltinStages(core::StageRegistry& registry) {
  // Each module adds its line here as its stages land (detection, segmentation, tracking,
  // frontend, estimator).
  odometry::registerStages(registry);
  detection::registerStages(registry);
  segmentation::registerStages(registry);
  tracking::registerStages(registry);
  estimator::registerStages(registry);
  frontend::registerStages(registry);
}

}  // namespace dynslam::system
