#pragma once
// Pinhole projection shared by the reprojection factors (static, non-rigid, rigid-object).
// The factors' residuals are in pixels: the front-end measures its tracking noise in pixels, and
// one isotropic pixel sigma stays isotropic whatever fx/fy are (a normalized-plane residual
// would need sigma/fx and sigma/fy to say the same thing).
#include <Eigen/Core>

namespace dynslam::estimator {

/// Points closer to the camera plane than this (metres, along the optical axis), or behind it,
/// have no projection: the factors' Evaluate() returns false there, which makes Ceres reject the
/// step that put them there. RGB-D cameras see nothing this close.
constexpr double kMinProjectionDepth = 1e-3;

struct PinholeCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;

  /// Pixel of a point in the camera's optical frame (x right, y down, z forward); when
  /// `jacobian` is given, d pixel / d point (2x3). The caller checks z >= kMinProjectionDepth.
  Eigen::Vector2d project(const Eigen::Vector3d& p_camera,
                          Eigen::Matrix<double, 2, 3>* jacobian = nullptr) const;

  /// The ray through a pixel on the z = 1 plane: [(u - cx) / fx, (v - cy) / fy, 1].
  Eigen::Vector3d bearing(const Eigen::Vector2d& pixel) const;
};

}  // namespace dynslam::estimator
