#include "dynslam/nav/SystemEstimateSource.h"

#include <dynslam/system/System.h>

#include <mrpt/maps/CPointsMap.h>

namespace dynslam::nav {

SystemEstimateSource::SystemEstimateSource(system::System& system) : system_(system) {
  system.subscribeToLocalization([this](const system::LocalizationUpdate& u) {
    std::lock_guard<std::mutex> lock(mutex_);
    poses_.add(u);
  });
  system.subscribeToMapUpdates([this](const system::MapUpdate& u) {
    auto points = std::dynamic_pointer_cast<const mrpt::maps::CPointsMap>(u.map);
    std::lock_guard<std::mutex> lock(mutex_);
    map_ = std::move(points);
  });
}

system::TrackingStatus SystemEstimateSource::status() const { return system_.status(); }

CameraPoses SystemEstimateSource::cameraPoses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return poses_;
}

std::vector<system::MovingObject> SystemEstimateSource::movingObjects() const {
  return system_.movingObjects();
}

std::shared_ptr<const mrpt::maps::CPointsMap> SystemEstimateSource::staticMap() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return map_;
}

}  // namespace dynslam::nav
