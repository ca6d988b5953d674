#include "dynslam/estimator/factors/CameraPosePriorFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

CameraPosePriorFactor::CameraPosePriorFactor(const Eigen::Isometry3d& T_world_camera,
                                             double sigma_translation_m, double sigma_rotation_rad)
    : p0_(T_world_camera.translation()),
      R0_(T_world_camera.rotation()),
      inv_sigma_p_(1.0 / sigma_translation_m),
      inv_sigma_r_(1.0 / sigma_rotation_rad) {}

bool CameraPosePriorFactor::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  const Eigen::Isometry3d T_wb = poseFromBlock(parameters[0]);
  const Eigen::Isometry3d T_bc = poseFromBlock(parameters[1]);
  const Eigen::Matrix3d R_wb = T_wb.rotation(), R_bc = T_bc.rotation();
  const Eigen::Vector3d p_bc = T_bc.translation();
  const Eigen::Vector3d phi = logSO3(R0_.transpose() * R_wb * R_bc);
  Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
  r.head<3>() = inv_sigma_p_ * (T_wb.translation() + R_wb * p_bc - p0_);
  r.tail<3>() = inv_sigma_r_ * phi;
  if (!jacobians) return true;
  // Right perturbations: R_wb Exp(d) R_bc = R_wb R_bc Exp(R_bc^T d); R_wb Exp(d) p ~ R_wb (p -
  // [p]x d).
  const Eigen::Matrix3d Jr_inv = inverseRightJacobianSO3(phi);
  if (jacobians[0]) {
    Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
    J.topLeftCorner<3, 3>() = inv_sigma_p_ * Eigen::Matrix3d::Identity();
    J.topRightCorner<3, 3>() = -inv_sigma_p_ * R_wb * skew(p_bc);
    J.bottomRightCorner<3, 3>() = inv_sigma_r_ * Jr_inv * R_bc.transpose();
    storePoseJacobian<6>(J, jacobians[0]);
  }
  if (jacobians[1]) {
    Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
    J.topLeftCorner<3, 3>() = inv_sigma_p_ * R_wb;
    J.bottomRightCorner<3, 3>() = inv_sigma_r_ * Jr_inv;
    storePoseJacobian<6>(J, jacobians[1]);
  }
  return true;
}

}  // namespace dynslam::estimator
