#pragma once
// The reference the estimate is compared with: an EstimateSource that hands the navigation
// adapter the simulator's truth (the camera's true poses, every person's true centre and
// velocity, the static obstacles from the scene's geometry), so that the same adapter and
// navigator run on perfect perception.
#include "nav_demo/StaticFootprint.h"

#include <dynslam/nav/EstimateSource.h>
#include <dynslam/sim/Agent.h>

#include <Eigen/Geometry>

#include <mutex>

namespace dynslam::navdemo {

class GroundTruthSource : public nav::EstimateSource {
 public:
  /// `agents` must outlive the source; the static points are the footprint's occupied cells
  /// repeated every 0.3 m up to 1.9 m.
  GroundTruthSource(const std::vector<sim::Agent>& agents, const StaticFootprint& statics);

  /// The true camera pose at simulated time t (s since the start; stamped start_time + t).
  void update(double t, double stamp, const Eigen::Isometry3d& T_world_camera);

  system::TrackingStatus status() const override;
  nav::CameraPoses cameraPoses() const override;
  std::vector<system::MovingObject> movingObjects() const override;
  std::shared_ptr<const mrpt::maps::CPointsMap> staticMap() const override { return map_; }

 private:
  const std::vector<sim::Agent>& agents_;
  std::shared_ptr<const mrpt::maps::CPointsMap> map_;
  mutable std::mutex mutex_;
  nav::CameraPoses poses_;
  double t_ = 0, stamp_ = 0;
};

/// A person's true centre and world velocity (central difference over +-0.05 s) at t.
system::MovingObject trueObject(const sim::Agent& agent, double t, double stamp);

}  // namespace dynslam::navdemo
