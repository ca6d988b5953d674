#include "dynslam/estimator/factors/GyroRotationFactor.h"

#include "dynslam/estimator/StateBlocks.h"
#include "dynslam/estimator/factors/TangentJacobian.h"

namespace dynslam::estimator {

GyroRotationFactor::GyroRotationFactor(const Eigen::Quaterniond& gamma,
                                       const Eigen::Matrix3d& covariance)
    : gamma_(gamma.normalized().toRotationMatrix()),
      sqrt_information_(sqrtInformationFromCovariance<3>(covariance)) {}

bool GyroRotationFactor::Evaluate(double const* const* parameters, double* residuals,
                                  double** jacobians) const {
  const Eigen::Matrix3d Ra = poseFromBlock(parameters[0]).rotation();
  const Eigen::Matrix3d Rb = poseFromBlock(parameters[1]).rotation();
  const Eigen::Matrix3d E = gamma_.transpose() * Ra.transpose() * Rb;
  const Eigen::Vector3d phi = logSO3(E);
  Eigen::Map<Eigen::Vector3d> out(residuals);
  out = sqrt_information_ * phi;
  if (!jacobians) return true;

  // Right perturbations R <- R Exp(d) (StateBlocks.h): E Exp(d_b) for b, and for a
  // gamma^T Exp(-d_a) Ra^T Rb = E Exp(-Rb^T Ra d_a); the positions do not enter.
  const Eigen::Matrix3d JrInv = inverseRightJacobianSO3(phi);
  using Jacobian = Eigen::Matrix<double, 3, 6>;
  if (jacobians[0]) {
    Jacobian J = Jacobian::Zero();
    J.rightCols<3>() = -JrInv * Rb.transpose() * Ra;
    storePoseJacobian<3>(sqrt_information_ * J, jacobians[0]);
  }
  if (jacobians[1]) {
    Jacobian J = Jacobian::Zero();
    J.rightCols<3>() = JrInv;
    storePoseJacobian<3>(sqrt_information_ * J, jacobians[1]);
  }
  return true;
}

}  // namespace dynslam::estimator
