#pragma once
// What the navigation adapter reads of a running SLAM system: its status, the camera's first,
// previous and latest poses, the moving objects and the newest static map. An interface, so that
// the adapter is tested without a pipeline (a fake source) and served by System in a program
// (SystemEstimateSource.h).
#include <dynslam/system/SystemOutputs.h>

#include <memory>
#include <optional>
#include <vector>

namespace mrpt::maps {
class CPointsMap;
}

namespace dynslam::nav {

/// The camera's poses the adapter needs: the first fixes the navigation frame, the previous and
/// the latest give the robot's pose and velocity.
struct CameraPoses {
  std::optional<system::LocalizationUpdate> first, previous, latest;
  /// Takes the next pose (the first one it gets stays `first`).
  void add(const system::LocalizationUpdate& u) {
    if (!first) first = u;
    previous = latest;
    latest = u;
  }
};

class EstimateSource {
 public:
  virtual ~EstimateSource() = default;
  // Thread-safe and cheap (copies of cached values): the navigator calls them at its own rate
  // while the SLAM system goes on.
  virtual system::TrackingStatus status() const = 0;
  virtual CameraPoses cameraPoses() const = 0;
  virtual std::vector<system::MovingObject> movingObjects() const = 0;
  /// The newest static map in the map frame (nullptr before the first); a new object whenever
  /// the map changes, never modified after it is handed out.
  virtual std::shared_ptr<const mrpt::maps::CPointsMap> staticMap() const = 0;
};

}  // namespace dynslam::nav
