#include "dynslam/estimator/factors/NonRigidConstantVelocityFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/CameraChain.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

NonRigidConstantVelocityFactor::NonRigidConstantVelocityFactor(const PinholeCamera& camera,
                                                               const Eigen::Vector2d& pixel_n,
                                                               double dt, double sigma_pixel)
    : camera_(camera), pixel_n_(pixel_n), dt_(dt), inv_sigma_(1.0 / sigma_pixel) {}

bool NonRigidConstantVelocityFactor::Evaluate(double const* const* parameters,
                                              double* residuals, double** jacobians) const {
  const Eigen::Map<const Eigen::Vector3d> p_w0(parameters[2]), v_w(parameters[3]);
  const Eigen::Vector3d p_wn = p_w0 + dt_ * v_w;
  WorldToCameraJacobians dp;
  const Eigen::Vector3d p_c = worldToCamera(poseFromBlock(parameters[0]),
                                            poseFromBlock(parameters[1]), p_wn,
                                            jacobians ? &dp : nullptr);
  if (p_c.z() < kMinProjectionDepth) return false;

  Eigen::Matrix<double, 2, 3> dpixel;
  Eigen::Map<Eigen::Vector2d> r(residuals);
  r = inv_sigma_ * (pixel_n_ - camera_.project(p_c, &dpixel));
  if (!jacobians) return true;

  const Eigen::Matrix<double, 2, 3> dr_dp = -inv_sigma_ * dpixel;
  if (jacobians[0]) storePoseJacobian<2>(dr_dp * dp.body_pose, jacobians[0]);
  if (jacobians[1]) storePoseJacobian<2>(dr_dp * dp.extrinsic, jacobians[1]);
  const Eigen::Matrix<double, 2, 3> dr_dpw = dr_dp * dp.point;
  if (jacobians[2]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J(jacobians[2]);
    J = dr_dpw;
  }
  if (jacobians[3]) {
    Eigen::Map<Eigen::Matrix<double, 2, 3, Eigen::RowMajor>> J(jacobians[3]);
    J = dt_ * dr_dpw;
  }
  return true;
}

}  // namespace dynslam::estimator
