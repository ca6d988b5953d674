#pragma once
// GNSS position (method.md section 5, beyond the paper): the antenna sits at a lever arm on the
// body, so the state predicts its world position p + R lever_arm; the caller hands the measured
// position already in the estimator's world frame (ENU from the first fix, aligned to the world)
// and its covariance (from HDOP):
//
//   r = S (p + R lever_arm - z),   S^T S = covariance^-1                              (3)
//
// Block: pose (7). The robust loss is the caller's choice.
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class GnssPositionFactor : public ceres::SizedCostFunction<3, 7> {
 public:
  GnssPositionFactor(const Eigen::Vector3d& measured_world_position,
                     const Eigen::Vector3d& lever_arm_body, const Eigen::Matrix3d& covariance);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector3d measured_;
  Eigen::Vector3d lever_arm_;
  Eigen::Matrix3d sqrt_information_;
};

}  // namespace dynslam::estimator
