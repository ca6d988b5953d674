#pragma once
namespace dynslam::core {
class StageRegistry;
}

namespace dynslam::odometry {
/// Adds RgbdOdometry.
void registerStages(core::StageRegistry& registry);
}  // namespace dynslam::odometry
