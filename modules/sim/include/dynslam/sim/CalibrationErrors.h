#pragma once
// [Calibration]: what a real device's calibration gets wrong, so the estimator's online
// calibration can be tested against a known truth. The rendering keeps the true camera mount and
// the true clocks; only what the estimator is told changes:
//   - time_offset_s: the camera's stamps run early or late against the IMU's,
//     t_imu = t_camera + time_offset_s (the estimator's t_d, VINS-Fusion's td), so a frame
//     taken at true time t is stamped t - time_offset_s;
//   - time_jitter_s: each camera stamp also gets N(0, jitter^2) (clipped at 3 sigma);
//   - cam_*_error: the "believed" camera-IMU extrinsic written to the rawlog's sensorPose is the
//     true one with this rotation (body axes, applied on the left) and offset added.
// The ground truth is stamped like the frames and holds the camera pose at the instant the stamp
// names on the IMU clock: what an estimator that knows t_d should report for that stamp.
#include <dynslam/core/Options.h>

#include <Eigen/Geometry>

#include <cstddef>

namespace dynslam::sim {

struct CalibrationErrorOptions : core::Options {
  double time_offset_s = 0;
  double time_jitter_s = 0;
  double cam_roll_error_deg = 0, cam_pitch_error_deg = 0, cam_yaw_error_deg = 0;
  double cam_x_error = 0, cam_y_error = 0, cam_z_error = 0;
  int seed = 1;  ///< set from [Scenario] seed (the jitter's draws), not a key

  void describe(core::OptionVisitor& v) override;

  bool changesStamps() const { return time_offset_s != 0 || time_jitter_s != 0; }
  /// The camera stamp (s since the start) of frame `index` taken at true time `t`.
  double cameraStamp(double t, std::size_t index) const;
  /// The extrinsic the rawlog says the camera has, given the true one.
  Eigen::Isometry3d believedCameraInBody(const Eigen::Isometry3d& T_body_camera) const;
};

}  // namespace dynslam::sim
