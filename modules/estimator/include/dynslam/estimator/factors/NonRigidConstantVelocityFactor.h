#pragma once
// r_D (method.md section 5, paper Eq. 17): a non-rigid dynamic feature (a point on a walking
// person) moves with constant world velocity between keyframes. Its states are its world
// position at a reference time t_n0 and its world velocity; at keyframe n (time t_n)
//
//   p_w(n) = p_w(n0) + v_w (t_n - t_n0)
//   r      = (u_n - pi(T_bc^-1 T_wb(n)^-1 p_w(n))) / sigma_pixel                  (2 residuals)
//
// Blocks: pose_n (7), extrinsic T_body_camera (7), p_w(n0) (3), v_w (3). Pixels and the
// behind-the-camera rule as StaticReprojectionFactor.h. The robust loss is the caller's choice.
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class NonRigidConstantVelocityFactor : public ceres::SizedCostFunction<2, 7, 7, 3, 3> {
 public:
  /// `dt` = t_n - t_n0, seconds (negative when n precedes the reference time).
  NonRigidConstantVelocityFactor(const PinholeCamera& camera, const Eigen::Vector2d& pixel_n,
                                 double dt, double sigma_pixel);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  PinholeCamera camera_;
  Eigen::Vector2d pixel_n_;
  double dt_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
