// Whether a window's motion observes the camera-IMU calibration it estimates. Under constant
// local linear and angular velocity a camera-IMU time offset cannot be told from a shift along
// the path, and without rotation the extrinsic cannot be told from the poses (Yang, Geneva,
// Eckenhoff, Huang, "Degenerate Motion Analysis for Aided INS With Online Spatial and Temporal
// Sensor Calibration", RA-L 2019). Left free there, the states follow the noise (a straight
// constant-velocity path: t_d 6.2 ms and the rotation 1.3 deg away from their priors in 10 s,
// docs/notes/calibration.md), so the window holds each until its motion observes it.
#pragma once

#include <Eigen/Geometry>

#include <vector>

namespace dynslam::estimator {

/// The least motion over a window that frees each calibration state ([Estimator]
/// calibration_min_* keys).
struct ExcitationThresholds {
  double min_rotation_deg = 2.0;      ///< extrinsic: rotation between two keyframes
  double min_rate_change = 0.05;      ///< time offset: rad/s, body angular rate
  double min_velocity_change = 0.05;  ///< time offset: m/s, body-frame velocity
};

/// One keyframe's motion at the window's current estimate.
struct KeyframeMotion {
  Eigen::Quaterniond q_world_body = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity_body = Eigen::Vector3d::Zero();  ///< rad/s (gyro)
};

struct CalibrationExcitation {
  double rotation_deg = 0;     ///< the largest rotation between the first keyframe and another
  double rate_change = 0;      ///< rad/s: largest distance of a keyframe's rate from the mean
  double velocity_change = 0;  ///< m/s: the same for the velocity in the body frame

  /// Non-constant local velocity: the angular rate or the body-frame velocity changes.
  bool observesTimeOffset(const ExcitationThresholds& t) const {
    return rate_change >= t.min_rate_change || velocity_change >= t.min_velocity_change;
  }
  bool observesExtrinsic(const ExcitationThresholds& t) const {
    return rotation_deg >= t.min_rotation_deg;
  }
};

/// The excitation of the keyframes' motion (none for fewer than two keyframes).
CalibrationExcitation measureExcitation(const std::vector<KeyframeMotion>& keyframes);

}  // namespace dynslam::estimator
