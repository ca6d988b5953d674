#pragma once
// The RGB-D depth measured at a non-rigid feature's pixel in keyframe n, against the depth its
// constant-velocity model (NonRigidConstantVelocityFactor.h) predicts there:
//
//   p_w(n) = p_w(n0) + v_w (t_n - t_n0),  p_c = T_bc^-1 T_wb(n)^-1 p_w(n)
//   r      = (p_c.z - d_n) / sigma_d(d_n)                                      (1 residual)
//
// Without it a point seen in two keyframes has 4 pixel residuals for 6 unknowns (position and
// velocity): the depth makes each observation a full 3-D one, as the static landmarks' depth
// factors do. Blocks: pose_n (7), extrinsic (7), p_w(n0) (3), v_w (3). sigma_d as
// DepthMeasurementFactor.h, evaluated at the measurement.
#include <dynslam/estimator/factors/DepthMeasurementFactor.h>

#include <ceres/sized_cost_function.h>

namespace dynslam::estimator {

class NonRigidDepthFactor : public ceres::SizedCostFunction<1, 7, 7, 3, 3> {
 public:
  /// `dt` = t_n - t_n0 (s); `measured_depth` > 0 (m).
  NonRigidDepthFactor(double dt, double measured_depth, const DepthNoiseModel& noise = {});

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double dt_;
  double measured_depth_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
