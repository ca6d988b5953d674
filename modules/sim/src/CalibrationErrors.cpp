#include "dynslam/sim/CalibrationErrors.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace dynslam::sim {

void CalibrationErrorOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  v.key("time_offset_s", time_offset_s, Range::closed(-0.2, 0.2),
        "s; the camera's stamps against the IMU's: t_imu = t_camera + time_offset_s (a frame "
        "taken at t is stamped t - time_offset_s; the estimator's t_d)");
  v.key("time_jitter_s", time_jitter_s, Range::closed(0, 0.005),
        "s; sigma of independent noise on each camera stamp (clipped at 3 sigma)");
  v.key("cam_roll_error_deg", cam_roll_error_deg, Range::closed(-20, 20),
        "deg; the believed camera-IMU rotation (the rawlog's sensorPose) is the true one turned "
        "by this roll, pitch and yaw about the body axes");
  v.key("cam_pitch_error_deg", cam_pitch_error_deg, Range::closed(-20, 20), "deg");
  v.key("cam_yaw_error_deg", cam_yaw_error_deg, Range::closed(-20, 20), "deg");
  v.key("cam_x_error", cam_x_error, Range::closed(-0.2, 0.2),
        "m; added to the believed camera position in the body frame");
  v.key("cam_y_error", cam_y_error, Range::closed(-0.2, 0.2), "m");
  v.key("cam_z_error", cam_z_error, Range::closed(-0.2, 0.2), "m");
}

double CalibrationErrorOptions::cameraStamp(double t, std::size_t index) const {
  double jitter = 0;
  if (time_jitter_s > 0) {
    // One generator per frame: frame i's stamp depends on the seed and i alone.
    std::mt19937_64 rng(std::uint64_t(seed) * 0x9E3779B97F4A7C15ull + index);
    std::normal_distribution<double> normal(0.0, 1.0);
    jitter = time_jitter_s * std::clamp(normal(rng), -3.0, 3.0);
  }
  return t - time_offset_s + jitter;
}

Eigen::Isometry3d CalibrationErrorOptions::believedCameraInBody(
    const Eigen::Isometry3d& T_body_camera) const {
  const double d = M_PI / 180;
  const Eigen::Matrix3d error =
      (Eigen::AngleAxisd(cam_yaw_error_deg * d, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(cam_pitch_error_deg * d, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(cam_roll_error_deg * d, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  Eigen::Isometry3d believed = T_body_camera;
  believed.linear() = error * T_body_camera.rotation();
  believed.translation() += Eigen::Vector3d(cam_x_error, cam_y_error, cam_z_error);
  return believed;
}

}  // namespace dynslam::sim
