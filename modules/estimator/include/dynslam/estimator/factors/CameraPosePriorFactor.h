#pragma once
// The window's gauge when the camera-IMU extrinsic is estimated: the first keyframe's camera
// pose T_world_body T_body_camera held where it is (tight sigmas) instead of its body pose. The
// IMU initialization put the world through the configured extrinsic; held by the body, every
// later correction of the extrinsic would turn and move the camera's whole trajectory from the
// poses already written (2 deg on indoor_people_high, docs/notes/calibration.md). Held by the
// camera, a correction moves the bodies and the gravity instead.
//
//   r = [(p_wb + R_wb p_bc - p0) / sigma_p ; Log(R0^T R_wb R_bc) / sigma_r]              (6)
//
// Blocks: the body pose T_world_body (7) and the extrinsic T_body_camera (7), PoseManifold.
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dynslam::estimator {

class CameraPosePriorFactor : public ceres::SizedCostFunction<6, 7, 7> {
 public:
  CameraPosePriorFactor(const Eigen::Isometry3d& T_world_camera, double sigma_translation_m,
                        double sigma_rotation_rad);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector3d p0_;
  Eigen::Matrix3d R0_;
  double inv_sigma_p_, inv_sigma_r_;
};

}  // namespace dynslam::estimator
