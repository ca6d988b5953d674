#pragma once
// The gyroscope's rotation between two consecutive keyframes while the window has no IMU
// factors (not the method): before the IMU initialization succeeds, and after a restart until
// it succeeds again. The window is then RGB-D only, and nothing kept its rotation from following
// features that move: a crowd crossing the view of a still camera turned the window, which the
// gyro would have read as still (docs/notes/estimator.md, 2026-11-28 (gyro_rotation_sigma)).
// With the preintegrated rotation gamma (ImuPreintegration, biases at their linearisation point)
// and body poses T_a, T_b (pose blocks),
//
//   r = S Log(gamma^T R_a^T R_b)                                                       (3)
//
// S the square root of the inverse of the covariance given at construction (the
// preintegration's rotation block plus the unknown gyro bias times the interval).
// Blocks: T_a (7), T_b (7).
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynslam::estimator {

class GyroRotationFactor : public ceres::SizedCostFunction<3, 7, 7> {
 public:
  /// `gamma`: R_a^T R_b as the gyro integrated it; `covariance` (3x3, rad^2) of its rotation
  /// vector.
  GyroRotationFactor(const Eigen::Quaterniond& gamma, const Eigen::Matrix3d& covariance);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Matrix3d gamma_;
  Eigen::Matrix3d sqrt_information_;
};

}  // namespace dynslam::estimator
