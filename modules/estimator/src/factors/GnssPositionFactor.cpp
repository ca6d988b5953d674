#include "dynslam/estimator/factors/GnssPositionFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

GnssPositionFactor::GnssPositionFactor(const Eigen::Vector3d& measured_world_position,
                                       const Eigen::Vector3d& lever_arm_body,
                                       const Eigen::Matrix3d& covariance)
    : measured_(measured_world_position),
      lever_arm_(lever_arm_body),
      sqrt_information_(sqrtInformationFromCovariance<3>(covariance)) {}

bool GnssPositionFactor::Evaluate(double const* const* parameters, double* residuals,
                                  double** jacobians) const {
  const Eigen::Isometry3d T_wb = poseFromBlock(parameters[0]);
  Eigen::Map<Eigen::Vector3d> r(residuals);
  r = sqrt_information_ * (T_wb * lever_arm_ - measured_);
  if (jacobians && jacobians[0]) {
    // R Exp(d) lever ~ R lever - R [lever]x d.
    Eigen::Matrix<double, 3, 6> J;
    J.leftCols<3>() = sqrt_information_;
    J.rightCols<3>() = -sqrt_information_ * T_wb.rotation() * skew(lever_arm_);
    storePoseJacobian<3>(J, jacobians[0]);
  }
  return true;
}

}  // namespace dynslam::estimator
