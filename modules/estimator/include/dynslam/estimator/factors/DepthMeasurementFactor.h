#pragma once
// The RGB-D depth measured at a static feature's first observation constrains its inverse depth
// (method.md section 5, r_lambda's "depth measurement residual"):
//
//   r = (lambda - 1/d) / sigma_lambda(d),   sigma_lambda(d) = sigma_d(d) / d^2
//
// with sigma_d(d) = a + b d^2, the structured-light / ToF depth noise (the simulator's model,
// sim::RgbdNoiseOptions; Kinect v1 measures b ~ 1.4e-3 /m). The residual is on the inverse depth,
// the parameter itself, so it is linear with a constant Jacobian; for sigma_d << d the Gaussian
// on d maps to a Gaussian on 1/d with the first-order sigma above. Both sigmas are evaluated at
// the measured depth, never at the estimate: a weight that depends on the estimate would let the
// solver lower the cost by pushing the feature away. Block: inverse depth (1).
#include <ceres/sized_cost_function.h>

namespace dynslam::estimator {

/// sigma_d(d) = a + b d^2 (metres). Defaults match sim::RgbdNoiseOptions.
struct DepthNoiseModel {
  double a = 0.001;   ///< m, the floor at short range
  double b = 0.0015;  ///< 1/m, the quadratic growth of triangulation-based sensors
  double sigma(double depth) const { return a + b * depth * depth; }
};

class DepthMeasurementFactor : public ceres::SizedCostFunction<1, 1> {
 public:
  /// `measured_depth` > 0, metres along the optical axis of the feature's first camera.
  DepthMeasurementFactor(double measured_depth, const DepthNoiseModel& noise = {});

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  double sigmaInverseDepth() const { return 1.0 / inv_sigma_; }

 private:
  double measured_inverse_depth_;
  double inv_sigma_;  ///< 1 / sigma_lambda
};

}  // namespace dynslam::estimator
