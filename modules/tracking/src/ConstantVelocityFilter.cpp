#include "dynslam/tracking/ConstantVelocityFilter.h"

#include <Eigen/Cholesky>

namespace dynslam::tracking {

ConstantVelocityFilter::ConstantVelocityFilter(const Eigen::Vector3d& position,
                                               const Eigen::Matrix3d& R, double speed_sigma) {
  x_ << position, Eigen::Vector3d::Zero();
  P_.setZero();
  P_.topLeftCorner<3, 3>() = R;
  P_.bottomRightCorner<3, 3>() = Eigen::Matrix3d::Identity() * speed_sigma * speed_sigma;
}

void ConstantVelocityFilter::predict(double dt, double acceleration_sigma) {
  if (!(dt > 0)) return;
  Matrix6 F = Matrix6::Identity();
  F.topRightCorner<3, 3>() = Eigen::Matrix3d::Identity() * dt;
  // The discretised white-noise acceleration: per axis q [dt^3/3 dt^2/2; dt^2/2 dt].
  const double q = acceleration_sigma * acceleration_sigma;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Matrix6 Q;
  Q << I * (q * dt * dt * dt / 3), I * (q * dt * dt / 2), I * (q * dt * dt / 2), I * (q * dt);
  x_ = F * x_;
  P_ = F * P_ * F.transpose() + Q;
}

double ConstantVelocityFilter::mahalanobis2(const Eigen::Vector3d& z,
                                            const Eigen::Matrix3d& R) const {
  const Eigen::Vector3d innovation = z - x_.head<3>();
  const Eigen::Matrix3d S = P_.topLeftCorner<3, 3>() + R;
  return innovation.dot(S.ldlt().solve(innovation));
}

void ConstantVelocityFilter::update(const Eigen::Vector3d& z, const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d S = P_.topLeftCorner<3, 3>() + R;
  // K = P H^T S^-1 with H = [I 0]: the first three columns of P.
  const Eigen::Matrix<double, 6, 3> PHt = P_.leftCols<3>();
  const Eigen::Matrix<double, 6, 3> K = S.ldlt().solve(PHt.transpose()).transpose();
  x_ += K * (z - x_.head<3>());
  // Joseph form: stays symmetric and positive over a long run.
  Matrix6 IKH = Matrix6::Identity();
  IKH.leftCols<3>() -= K;
  P_ = IKH * P_ * IKH.transpose() + K * R * K.transpose();
}

}  // namespace dynslam::tracking
