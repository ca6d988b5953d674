#pragma once
// EstimateSource served by a dynslam::system::System: it subscribes to the system's pose and map
// updates, so it must be made before the system's first observation.
#include <dynslam/nav/EstimateSource.h>

#include <mutex>

namespace dynslam::system {
class System;
}

namespace dynslam::nav {

class SystemEstimateSource : public EstimateSource {
 public:
  /// `system` must outlive this source.
  explicit SystemEstimateSource(system::System& system);

  system::TrackingStatus status() const override;
  CameraPoses cameraPoses() const override;
  std::vector<system::MovingObject> movingObjects() const override;
  std::shared_ptr<const mrpt::maps::CPointsMap> staticMap() const override;

 private:
  const system::System& system_;
  mutable std::mutex mutex_;
  CameraPoses poses_;
  std::shared_ptr<const mrpt::maps::CPointsMap> map_;
};

}  // namespace dynslam::nav
