#pragma once
// Priors that keep online calibration at its configured value unless the data say otherwise
// (VINS-Fusion's estimate_td / estimate_extrinsic, OpenVINS's calib_cam_*): without them the
// camera-IMU time offset and extrinsic drift wherever the motion leaves them unobservable (no
// rotation, constant velocity). They are never marginalised: a constant term of every solve.
//
//   TimeOffsetPriorFactor:  r = (t_d - t_d0) / sigma                                     (1)
//   ExtrinsicPriorFactor:   r = [(p - p0) / sigma_p ; Log(R0^T R) / sigma_r]             (6)
//
// Blocks: the time offset (1, s); the extrinsic T_body_camera (7, PoseManifold).
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynslam::estimator {

class TimeOffsetPriorFactor : public ceres::SizedCostFunction<1, 1> {
 public:
  TimeOffsetPriorFactor(double prior_s, double sigma_s);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  double prior_, inv_sigma_;
};

class ExtrinsicPriorFactor : public ceres::SizedCostFunction<6, 7> {
 public:
  ExtrinsicPriorFactor(const Eigen::Isometry3d& prior, double sigma_translation_m,
                       double sigma_rotation_rad);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector3d p0_;
  Eigen::Matrix3d R0_;
  double inv_sigma_p_, inv_sigma_r_;
};

}  // namespace dynslam::estimator
