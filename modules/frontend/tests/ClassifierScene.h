#pragma once
// The synthetic scene the classifier's tests run on: a camera that moves and turns (IMU gyro
// given) in front of a textured background, a walking person, a standing person, a parked car
// and a driving car, each with a track and a full-box mask; features with exact depths.
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/DynamicClassifier.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace dynslam::frontend::testing {

extern const core::CameraIntrinsics kCamera;
constexpr double kDt = 1.0 / 30;
constexpr double kYawRate = 0.3;  // rad/s, the camera turns about its y axis

struct Object {
  int track_id;
  core::MotionModel model;
  Eigen::Vector3d velocity;             // m/s, world
  std::vector<Eigen::Vector3d> points;  // world, at t = 0
};

/// Camera = world axes at t = 0, moving along x at 0.3 m/s and turning at kYawRate; gyro and
/// camera axes coincide (identity extrinsics).
Eigen::Isometry3d cameraPose(double t);

struct Scene {
  std::vector<Eigen::Vector3d> background;
  std::vector<Object> objects;

  Scene();
  /// Frame k with features (ids: background i, object j point i -> 1000 (j + 1) + i), one mask
  /// per object (its features' bounding box, slightly grown), one track per object.
  core::Frame frame(int k) const;
};

/// Frames 0-14 of the scene through a classifier with `params`, the masks of frames 12-14 edited
/// by `editMasks` (a detection missed, a mask grown over another object); the last frame.
template <class EditMasks>
core::Frame classifyWithEditedMasks(const DynamicClassifierParams& params, EditMasks editMasks) {
  const Scene scene;
  DynamicClassifier classifier(params);
  core::Frame f;
  for (int k = 0; k < 15; ++k) {
    f = scene.frame(k);
    if (k >= 12) editMasks(f.object_masks);
    classifier.process(f);
  }
  return f;
}

}  // namespace dynslam::frontend::testing
