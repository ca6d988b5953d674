#pragma once
// Random but plausible states for the factor tests: poses, a camera mounted on the body, points
// in front of it. Deterministic per seed.
#include <dynslam/estimator/StateBlocks.h>
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <ceres/cost_function.h>
#include <gtest/gtest.h>

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

/// The factor's residual at the given block values (Evaluate must succeed).
template <int N>
Eigen::Matrix<double, N, 1> residualAt(const ceres::CostFunction& f,
                                       std::vector<std::vector<double>> blocks) {
  std::vector<double*> p;
  for (auto& x : blocks) p.push_back(x.data());
  Eigen::Matrix<double, N, 1> r;
  EXPECT_TRUE(f.Evaluate(p.data(), r.data(), nullptr));
  return r;
}

/// A static feature seen from two keyframes i and j (StaticReprojectionFactor's geometry).
struct StaticScene {
  Eigen::Isometry3d T_wbi, T_wbj, T_bc;
  Eigen::Vector2d pixel_i, pixel_j;  ///< pixel_j exact (noise added by the tests that want it)
  double inverse_depth = 0;  ///< in camera i
  double depth_j = 0;        ///< the point's depth in camera j
};

inline StaticScene randomStaticScene(std::mt19937& rng) {
  const PinholeCamera cam = testCamera();
  for (;;) {
    StaticScene s;
    s.T_wbi = randomPose(rng, 5.0, M_PI);
    s.T_bc = randomExtrinsic(rng);
    s.T_wbj = s.T_wbi * randomPose(rng, 0.3, 0.2);
    const Eigen::Vector3d p_ci = randomPointInView(rng, cam);
    s.pixel_i = cam.project(p_ci);
    s.inverse_depth = 1.0 / p_ci.z();
    const Eigen::Vector3d p_cj = s.T_bc.inverse() * s.T_wbj.inverse() * s.T_wbi * s.T_bc * p_ci;
    if (p_cj.z() < 0.5) continue;  // keep it well in front of camera j
    s.pixel_j = cam.project(p_cj);
    s.depth_j = p_cj.z();
    return s;
  }
}

inline std::vector<std::vector<double>> blocksOf(const StaticScene& s) {
  return {poseBlock(s.T_wbi), poseBlock(s.T_wbj), poseBlock(s.T_bc), {s.inverse_depth}};
}

}  // namespace dynslam::estimator::testing
