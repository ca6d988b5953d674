#pragma once
// The depth measured in a later keyframe j at a static feature's pixel, against the depth its
// anchored inverse-depth point (StaticReprojectionFactor.h) predicts there:
//
//   p_cj = T_bc^-1 T_wb(j)^-1 T_wb(i) T_bc (bearing(u_i) / lambda)
//   r    = (p_cj.z - d_j) / sigma_d(d_j)                                   (1 residual)
//
// Optional beside DepthMeasurementFactor: it ties the keyframe poses' translation to the metric
// depth of every frame, not only the first. The residual is in metres because p_cj.z is what the
// state predicts directly; sigma_d (DepthMeasurementFactor.h) is evaluated at the measurement.
// Blocks: pose_i (7), pose_j (7), extrinsic T_body_camera (7), inverse depth (1).
// Evaluate() returns false for lambda <= 0 (no point); behind camera j the residual stays defined.
#include <dynslam/estimator/factors/DepthMeasurementFactor.h>
#include <dynslam/estimator/factors/PinholeProjection.h>

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class TransferredDepthFactor : public ceres::SizedCostFunction<1, 7, 7, 7, 1> {
 public:
  TransferredDepthFactor(const PinholeCamera& camera, const Eigen::Vector2d& pixel_i,
                         double measured_depth_j, const DepthNoiseModel& noise = {});

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector3d bearing_i_;
  double measured_depth_j_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
