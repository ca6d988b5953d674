#pragma once
// A linear Kalman filter of a point's position and velocity in 3-D with white-noise
// acceleration (the ObjectStates stage's filter of a body centre). State (p, v), world axes.
#include <Eigen/Core>

namespace dynslam::tracking {

class ConstantVelocityFilter {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  /// Starts at `position` (covariance `R`), at rest with sigma `speed_sigma` per axis.
  ConstantVelocityFilter(const Eigen::Vector3d& position, const Eigen::Matrix3d& R,
                         double speed_sigma);

  /// Moves the state `dt` seconds on; the acceleration is white noise of spectral density
  /// acceleration_sigma^2 ((m/s^2)^2 / Hz) on each axis.
  void predict(double dt, double acceleration_sigma);
  /// Squared Mahalanobis distance of a position measurement `z` (covariance `R`) from the state.
  double mahalanobis2(const Eigen::Vector3d& z, const Eigen::Matrix3d& R) const;
  void update(const Eigen::Vector3d& z, const Eigen::Matrix3d& R);

  Eigen::Vector3d position() const { return x_.head<3>(); }
  Eigen::Vector3d velocity() const { return x_.tail<3>(); }
  const Matrix6& covariance() const { return P_; }

 private:
  Vector6 x_;
  Matrix6 P_;
};

}  // namespace dynslam::tracking
