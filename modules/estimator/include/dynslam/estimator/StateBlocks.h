#pragma once
// How the sliding-window estimator lays its states out in Ceres parameter blocks, shared by
// every factor (method.md section 5; the layout VINS-Fusion uses):
//   pose block (7):       [px py pz qx qy qz qw]  T_world_body: position and unit quaternion in
//                         Eigen's memory order (x, y, z, w), body = IMU frame;
//                         object poses L_n use the same block (T_world_object).
//   speed-bias block (9): [vx vy vz bax bay baz bgx bgy bgz]  world velocity, accelerometer bias,
//                         gyroscope bias;
//   inverse depth (1):    1 / depth of a static feature in its first observing camera frame;
//   point (3) / velocity (3): world position and world velocity of a non-rigid feature.
//
// Pose blocks live on PoseManifold: x [+] delta = (p + dp, q * Exp(dtheta)) with delta =
// [dp, dtheta] (rotation perturbed on the right, in the body frame). Factors compute their
// Jacobian with respect to delta (6 columns) and store it in the first 6 columns of the 7-column
// block Jacobian Ceres asks for, the 7th column zero; PoseManifold::PlusJacobian is [I6; 0], so
// Ceres' product J_ambient * PlusJacobian gives back exactly the tangent Jacobian. This is the
// VINS-Fusion convention: the analytic Jacobians are written in the tangent space where they are
// simple, and the tests (FactorJacobianCheck.h) compare them with numeric differentiation along
// the same Plus.
#include <ceres/manifold.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynslam::estimator {

constexpr int kPoseSize = 7;
constexpr int kPoseTangentSize = 6;
constexpr int kSpeedBiasSize = 9;

/// Pose block -> isometry, and back.
Eigen::Isometry3d poseFromBlock(const double* block);
void poseToBlock(const Eigen::Isometry3d& pose, double* block);

/// The nearest rigid transform (rotation re-orthonormalised through a unit quaternion): products
/// of many poses drift off SO(3) in floating point, and a slightly scaled rotation compounds
/// when a pose is carried forward frame after frame.
Eigen::Isometry3d nearestRigid(const Eigen::Isometry3d& T);

/// SO(3) exponential of a rotation vector (small angles handled).
Eigen::Quaterniond quaternionExp(const Eigen::Vector3d& theta);
/// SO(3) logarithm: the rotation vector of R (|result| <= pi).
Eigen::Vector3d logSO3(const Eigen::Matrix3d& R);
/// Right Jacobian of SO(3) at phi: Exp(phi + d) ~ Exp(phi) Exp(Jr(phi) d).
Eigen::Matrix3d rightJacobianSO3(const Eigen::Vector3d& phi);
/// Its inverse: Log(Exp(phi) Exp(d)) ~ phi + Jr^-1(phi) d.
Eigen::Matrix3d inverseRightJacobianSO3(const Eigen::Vector3d& phi);

/// Skew-symmetric matrix [v]x.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

class PoseManifold : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kPoseSize; }
  int TangentSize() const override { return kPoseTangentSize; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  /// [I6; 0]: see the file comment.
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

}  // namespace dynslam::estimator
