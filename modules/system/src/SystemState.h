#pragma once
// What System's getters read while the processing thread goes on: the latest pose, the camera's
// velocity, the moving objects and the status, replaced under a mutex after every frame.
#include <dynslam/system/SystemOutputs.h>

#include <Eigen/Geometry>

#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

namespace dynslam::core {
struct Frame;
}

namespace dynslam::system {

class SystemState {
 public:
  /// An object not posed for this long (s, stamps) is no longer listed.
  static constexpr double kObjectMemoryS = 1.0;

  void update(const core::Frame& frame);

  std::optional<LocalizationUpdate> latestPose() const;
  std::optional<Eigen::Vector3d> latestVelocity() const;
  std::vector<MovingObject> movingObjects() const;
  TrackingStatus status() const;
  std::size_t frames() const;

 private:
  struct Posed {
    double t = 0;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  };
  struct Object {
    MovingObject out;
    Posed last;
  };
  void updateObjects(const core::Frame& frame);

  mutable std::mutex mutex_;
  std::size_t frames_ = 0;
  TrackingStatus status_ = TrackingStatus::Initializing;
  std::optional<LocalizationUpdate> pose_;
  std::optional<Posed> camera_, previousCamera_;
  std::map<int, Object> objects_;
};

}  // namespace dynslam::system
