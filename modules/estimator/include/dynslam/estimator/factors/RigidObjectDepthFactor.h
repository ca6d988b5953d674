#pragma once
// The RGB-D depth measured at a rigid-object feature's pixel in keyframe n, against the depth the
// object model (RigidObjectReprojectionFactor.h) predicts there:
//
//   m_n = L_n m_obj,  p_c = T_bc^-1 T_wb(n)^-1 m_n
//   r   = (p_c.z - d_n) / sigma_d(d_n)                                         (1 residual)
//
// With the two pixel residuals of r_O each observation becomes a full 3-D one, as the static
// landmarks' and the non-rigid points' depth factors do: without it an object seen in a few
// keyframes leaves its scale (distance) to the pixels alone. Blocks: pose_n (body, 7), extrinsic
// T_body_camera (7), object pose L_n = T_world_object (7), m_obj (3). sigma_d as
// DepthMeasurementFactor.h, evaluated at the measurement.
#include <dynslam/estimator/factors/DepthMeasurementFactor.h>

#include <ceres/sized_cost_function.h>

namespace dynslam::estimator {

class RigidObjectDepthFactor : public ceres::SizedCostFunction<1, 7, 7, 7, 3> {
 public:
  /// `measured_depth` > 0 (m).
  explicit RigidObjectDepthFactor(double measured_depth, const DepthNoiseModel& noise = {});

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double measured_depth_;
  double inv_sigma_;
};

}  // namespace dynslam::estimator
