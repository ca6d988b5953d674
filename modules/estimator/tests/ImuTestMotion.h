#pragma once
// An analytic body motion and the exact IMU samples it produces, for the preintegration and IMU
// factor tests: position a smooth 3-D curve, orientation Exp(theta(t)) with theta linear in t
// (so the body rate is constant and known exactly).
#include <dynslam/estimator/StateBlocks.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace dynslam::estimator::testing {

struct MotionState {
  Eigen::Vector3d p, v, a;  // world position, velocity, acceleration
  Eigen::Quaterniond q;     // R_world_body
};

inline const Eigen::Vector3d kTestGravity(0, 0, -9.81);

inline MotionState motionAt(double t) {
  MotionState s;
  s.p = Eigen::Vector3d(std::sin(t), 0.5 * std::cos(1.3 * t), 0.2 * std::sin(0.7 * t));
  s.v = Eigen::Vector3d(std::cos(t), -0.65 * std::sin(1.3 * t), 0.14 * std::cos(0.7 * t));
  s.a = Eigen::Vector3d(-std::sin(t), -0.845 * std::cos(1.3 * t), -0.098 * std::sin(0.7 * t));
  s.q = quaternionExp(Eigen::Vector3d(0.3, -0.5, 0.8) * t) *
        quaternionExp(Eigen::Vector3d(0.1, 0.2, 0.3));
  return s;
}

/// Body rate of motionAt: q(t) = Exp(w t) q0, so the body-frame rate is q0^-1 w.
inline Eigen::Vector3d bodyRate() {
  return quaternionExp(Eigen::Vector3d(0.1, 0.2, 0.3)).inverse() * Eigen::Vector3d(0.3, -0.5, 0.8);
}

/// The accelerometer's specific force at t (no bias, no noise).
inline Eigen::Vector3d specificForce(double t) {
  const MotionState s = motionAt(t);
  return s.q.inverse() * (s.a - kTestGravity);
}

}  // namespace dynslam::estimator::testing
