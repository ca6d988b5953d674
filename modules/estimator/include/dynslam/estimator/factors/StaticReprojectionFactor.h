#pragma once
// r_lambda (method.md section 5): a static feature first seen at pixel u_i in keyframe i,
// parameterised by its inverse depth in camera i, observed again at pixel u_j in keyframe j.
//
//   p_cj = T_bc^-1 T_wb(j)^-1 T_wb(i) T_bc (bearing(u_i) / lambda)
//   r    = (u_j - pi(p_cj)) / sigma_pixel                                   (2 residuals)
//
// Parameter blocks: pose_i (7), pose_j (7), extrinsic T_body_camera (7, usually held constant),
// inverse depth lambda (1). The residual is in pixels (PinholeProjection.h says why), whitened by
// the pixel sigma given at construction; u_i is taken as exact, the usual anchored-inverse-depth
// approximation (VINS-Fusion's). The robust loss is the caller's choice.
//
// Evaluate() returns false when the point is not in front of camera j (kMinProjectionDepth) or
// lambda <= 0: Ceres then rejects the step. The window adds the factor only for features in front
// of both cameras at the current estimate (and bounds lambda from below, e.g. 1e-3).
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class StaticReprojectionFactor : public ceres::SizedCostFunction<2, 7, 7, 7, 1> {
 public:
  StaticReprojectionFactor(const PinholeCamera& camera, const Eigen::Vector2d& pixel_i,
                           const Eigen::Vector2d& pixel_j, double sigma_pixel);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  PinholeCamera camera_;
  Eigen::Vector3d bearing_i_;
  Eigen::Vector2d pixel_j_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
