#pragma once
// Small pieces every factor needs to hand Ceres its Jacobians in the layout StateBlocks.h fixes,
// and to whiten its residual.
#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace dynslam::estimator {

/// Writes a Jacobian with respect to a pose block's tangent [dp, dtheta] (Rows x 6) into the
/// Rows x 7 row-major block Jacobian Ceres asks for, with the 7th column zero (StateBlocks.h).
template <int Rows>
void storePoseJacobian(const Eigen::Matrix<double, Rows, 6>& tangent, double* block) {
  Eigen::Map<Eigen::Matrix<double, Rows, 7, Eigen::RowMajor>> out(block);
  out.template leftCols<6>() = tangent;
  out.col(6).setZero();
}

/// S with S^T S = covariance^-1, so S * r has unit covariance: the inverse of the lower
/// Cholesky factor of the covariance.
template <int N>
Eigen::Matrix<double, N, N> sqrtInformationFromCovariance(
    const Eigen::Matrix<double, N, N>& covariance) {
  const Eigen::Matrix<double, N, N> L = covariance.llt().matrixL();
  return L.inverse();
}

/// S with S^T S = information: the transpose of its lower Cholesky factor.
template <int N>
Eigen::Matrix<double, N, N> sqrtInformationFromInformation(
    const Eigen::Matrix<double, N, N>& information) {
  const Eigen::Matrix<double, N, N> L = information.llt().matrixL();
  return L.transpose();
}

}  // namespace dynslam::estimator
