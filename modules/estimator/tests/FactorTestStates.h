#pragma once
// Random but plausible states for the factor tests: poses, a camera mounted on the body, points
// in front of it. Deterministic per seed.
#include <dynslam/estimator/StateBlocks.h>
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace dynslam::estimator::testing {

inline PinholeCamera testCamera() { return PinholeCamera{525.0, 520.0, 319.5, 239.5}; }

inline std::vector<double> poseBlock(const Eigen::Isometry3d& T) {
  std::vector<double> b(kPoseSize);
  poseToBlock(T, b.data());
  return b;
}

inline Eigen::Vector3d uniformVector(std::mt19937& rng, double halfWidth) {
  std::uniform_real_distribution<double> u(-halfWidth, halfWidth);
  return {u(rng), u(rng), u(rng)};
}

/// A pose with translation in [-t, t]^3 and a rotation of up to `angle` rad about a random axis.
inline Eigen::Isometry3d randomPose(std::mt19937& rng, double t, double angle) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d axis = uniformVector(rng, 1.0).normalized();
  std::uniform_real_distribution<double> a(0.0, angle);
  T.linear() = quaternionExp(a(rng) * axis).toRotationMatrix();
  T.translation() = uniformVector(rng, t);
  return T;
}

/// A camera looking forward along the body's x axis (optical z = body x, as on a robot), a few
/// centimetres off the body origin and slightly misaligned.
inline Eigen::Isometry3d randomExtrinsic(std::mt19937& rng) {
  Eigen::Matrix3d opticalToBody;
  opticalToBody << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = opticalToBody * quaternionExp(uniformVector(rng, 0.05)).toRotationMatrix();
  T.translation() = uniformVector(rng, 0.1);
  return T;
}

/// A point in front of the camera: a pixel inside a 640x480 image at depth 1..6 m.
inline Eigen::Vector3d randomPointInView(std::mt19937& rng, const PinholeCamera& cam) {
  std::uniform_real_distribution<double> u(20, 620), v(20, 460), d(1.0, 6.0);
  return cam.bearing({u(rng), v(rng)}) * d(rng);
}

}  // namespace dynslam::estimator::testing
