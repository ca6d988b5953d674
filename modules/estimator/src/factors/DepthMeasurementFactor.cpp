#include "dynslam/estimator/factors/DepthMeasurementFactor.h"

namespace dynslam::estimator {

DepthMeasurementFactor::DepthMeasurementFactor(double measured_depth,
                                               const DepthNoiseModel& noise)
    : measured_inverse_depth_(1.0 / measured_depth),
      inv_sigma_(measured_depth * measured_depth / noise.sigma(measured_depth)) {}

bool DepthMeasurementFactor::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  residuals[0] = inv_sigma_ * (parameters[0][0] - measured_inverse_depth_);
  if (jacobians && jacobians[0]) jacobians[0][0] = inv_sigma_;
  return true;
}

}  // namespace dynslam::estimator
