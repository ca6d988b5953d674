#include "dynslam/estimator/factors/CalibrationPriorFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

TimeOffsetPriorFactor::TimeOffsetPriorFactor(double prior_s, double sigma_s)
    : prior_(prior_s), inv_sigma_(1.0 / sigma_s) {}

bool TimeOffsetPriorFactor::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  residuals[0] = inv_sigma_ * (parameters[0][0] - prior_);
  if (jacobians && jacobians[0]) jacobians[0][0] = inv_sigma_;
  return true;
}

ExtrinsicPriorFactor::ExtrinsicPriorFactor(const Eigen::Isometry3d& prior,
                                           double sigma_translation_m, double sigma_rotation_rad)
    : p0_(prior.translation()),
      R0_(prior.rotation()),
      inv_sigma_p_(1.0 / sigma_translation_m),
      inv_sigma_r_(1.0 / sigma_rotation_rad) {}

bool ExtrinsicPriorFactor::Evaluate(double const* const* parameters, double* residuals,
                                    double** jacobians) const {
  const Eigen::Isometry3d T = poseFromBlock(parameters[0]);
  const Eigen::Vector3d phi = logSO3(R0_.transpose() * T.rotation());
  Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
  r.head<3>() = inv_sigma_p_ * (T.translation() - p0_);
  r.tail<3>() = inv_sigma_r_ * phi;
  if (!jacobians || !jacobians[0]) return true;
  // Right perturbation R <- R Exp(d): Log(R0^T R Exp(d)) ~ phi + Jr^-1(phi) d.
  Eigen::Matrix<double, 6, 6> J = Eigen::Matrix<double, 6, 6>::Zero();
  J.topLeftCorner<3, 3>() = inv_sigma_p_ * Eigen::Matrix3d::Identity();
  J.bottomRightCorner<3, 3>() = inv_sigma_r_ * inverseRightJacobianSO3(phi);
  storePoseJacobian<6>(J, jacobians[0]);
  return true;
}

}  // namespace dynslam::estimator
