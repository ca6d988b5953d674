#include "dynslam/estimator/factors/StaticReprojectionFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

StaticReprojectionFactor::StaticReprojectionFactor(
    const PinholeCamera& camera, const Eigen::Vector2d& pixel_i, const Eigen::Vector2d& pixel_j,
    double sigma_pixel, const Eigen::Vector2d& velocity_i, const Eigen::Vector2d& velocity_j)
    : camera_(camera),
      pixel_i_(pixel_i),
      pixel_j_(pixel_j),
      velocity_i_(velocity_i),
      velocity_j_(velocity_j),
      inv_sigma_(1.0 / sigma_pixel) {}

bool StaticReprojectionFactor::Evaluate(double const* const* parameters, double* residuals,
                                        double** jacobians) const {
  const double inverse_depth = parameters[3][0];
  if (!(inverse_depth > 0)) return false;
  const Eigen::Isometry3d T_wbi = poseFromBlock(parameters[0]);
  const Eigen::Isometry3d T_wbj = poseFromBlock(parameters[1]);
  const Eigen::Isometry3d T_bc = poseFromBlock(parameters[2]);
  const double td = parameters[4][0];

  InverseDepthTransferJacobians dp;
  const Eigen::Vector3d p_cj =
      transferInverseDepthPoint(T_wbi, T_wbj, T_bc, camera_.bearing(pixel_i_ - td * velocity_i_),
                                inverse_depth, jacobians ? &dp : nullptr);
  if (p_cj.z() < kMinProjectionDepth) return false;

  Eigen::Matrix<double, 2, 3> dpixel;
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = inv_sigma_ * (pixel_j_ - td * velocity_j_ - camera_.project(p_cj, &dpixel));
  if (!jacobians) return true;

  // r = (u - pi(p)) / sigma: dr/dx = -(1/sigma) dpi/dp dp/dx.
  const Eigen::Matrix<double, 2, 3> dr_dp = -inv_sigma_ * dpixel;
  if (jacobians[0]) storePoseJacobian<2>(dr_dp * dp.pose_i, jacobians[0]);
  if (jacobians[1]) storePoseJacobian<2>(dr_dp * dp.pose_j, jacobians[1]);
  if (jacobians[2]) storePoseJacobian<2>(dr_dp * dp.extrinsic, jacobians[2]);
  if (jacobians[3]) {
    Eigen::Map<Eigen::Vector2d> dr_dlambda(jacobians[3]);
    dr_dlambda = dr_dp * dp.inverse_depth;
  }
  if (jacobians[4]) {
    // d bearing(u - td v) / d td = -(v_x / fx, v_y / fy, 0).
    const Eigen::Vector3d dbearing(-velocity_i_.x() / camera_.fx, -velocity_i_.y() / camera_.fy,
                                   0.0);
    Eigen::Map<Eigen::Vector2d> dr_dtd(jacobians[4]);
    dr_dtd = -inv_sigma_ * velocity_j_ + dr_dp * (dp.bearing * dbearing);
  }
  return true;
}

}  // namespace dynslam::estimator
