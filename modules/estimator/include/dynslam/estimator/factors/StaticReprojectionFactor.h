#pragma once
// r_lambda (method.md section 5): a static feature first seen at pixel u_i in keyframe i,
// parameterised by its inverse depth in camera i, observed again at pixel u_j in keyframe j.
//
//   u'_k = u_k - t_d v_k                 (k = i, j: the pixel moved to the state's time)
//   p_cj = T_bc^-1 T_wb(j)^-1 T_wb(i) T_bc (bearing(u'_i) / lambda)
//   r    = (u'_j - pi(p_cj)) / sigma_pixel                                  (2 residuals)
//
// Camera-IMU time offset t_d (VINS-Fusion's td, with its sign: t_imu = t_camera + t_d): a
// keyframe's state is the body at its camera stamp read on the IMU clock, but the image was
// taken t_d later; a feature moving at v_k px/s (its tracked image velocity) was at u_k - t_d v_k
// when the state was. VINS-Fusion also moves the IMU integration to the new t_d; here the states
// stay at the stamps and the whole offset acts through the pixels, so t_d needs no re-cut of the
// IMU stream (an equivalent first-order formulation).
//
// Parameter blocks: pose_i (7), pose_j (7), extrinsic T_body_camera (7, held constant unless the
// window estimates it), inverse depth lambda (1), time offset t_d (1, s; held constant unless
// estimated). The residual is in pixels (PinholeProjection.h says why), whitened by
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

class StaticReprojectionFactor : public ceres::SizedCostFunction<2, 7, 7, 7, 1, 1> {
 public:
  /// velocity_i, velocity_j: the features' image velocities (px/s) in keyframes i and j.
  StaticReprojectionFactor(const PinholeCamera& camera, const Eigen::Vector2d& pixel_i,
                           const Eigen::Vector2d& pixel_j, double sigma_pixel,
                           const Eigen::Vector2d& velocity_i = Eigen::Vector2d::Zero(),
                           const Eigen::Vector2d& velocity_j = Eigen::Vector2d::Zero());

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  PinholeCamera camera_;
  Eigen::Vector2d pixel_i_, pixel_j_;
  Eigen::Vector2d velocity_i_, velocity_j_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
