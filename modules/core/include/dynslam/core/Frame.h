#pragma once
// The unit of work that flows through the pipeline: one RGB-D image pair plus everything the
// other sensors said since the previous one. Stages read what earlier stages wrote and add
// their own output. Kept free of MRPT headers: every stage includes this file.
#include <dynslam/core/Features.h>
#include <dynslam/core/ObjectState.h>
#include <dynslam/core/Perception.h>
#include <dynslam/core/Trajectory.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace dynslam::core {

/// Pinhole intrinsics of the colour camera (depth is registered to it), pixels.
struct CameraIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  int width = 0, height = 0;
};

/// One IMU sample. A device may give only part of it (TUM's accelerometer-only IMU): the
/// has_* flags say which vectors hold measurements.
struct ImuSample {
  double t = 0.0;                                  ///< seconds
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();  ///< rad/s, IMU frame
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();   ///< m/s^2, IMU frame, gravity included
  bool has_gyro = false;
  bool has_acc = false;
};

/// One GNSS fix (NMEA GGA) with its position in the local ENU frame whose origin is the first
/// fix of the run.
struct GnssFix {
  double t = 0.0;  ///< seconds
  double latitude_deg = 0, longitude_deg = 0, altitude_m = 0;
  int fix_quality = 0;  ///< GGA quality: 0 invalid, 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float
  int satellites = 0;
  double hdop = 0;
  Eigen::Vector3d enu = Eigen::Vector3d::Zero();  ///< metres east, north, up from the origin
};

/// What the estimator did on a frame it made a keyframe (the runner writes keyframes.csv), so a
/// run's drift can be traced to the keyframes where the window saw little or the IMU states
/// moved.
struct KeyframeRecord {
  std::string reason;         ///< first, parallax, interval or few_shared (KeyframeSelector)
  int static_features = 0;    ///< landmark observations given to the window
  int shared_features = 0;    ///< of the features, those the last keyframe had too
  int nonrigid_features = 0;  ///< r_D observations (dynamic_handling = full)
  int rigid_objects = 0;      ///< objects with r_O / r_om factors in the solve
  double solve_ms = 0;
  int iterations = 0;
  bool restarted = false;        ///< the solve failed and the window started again here
  bool visual_inertial = false;  ///< the window had the IMU (initialized) at this keyframe
  /// The keyframe's states after the solve: world velocity (m/s), accelerometer (m/s^2) and
  /// gyroscope (rad/s) biases; zero while the window is RGB-D only.
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acc_bias = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();
  /// The online calibration after the solve: the camera-IMU time offset (s) and the extrinsic's
  /// change from its configured value (rotation vector, rad; translation, m).
  double time_offset = 0;
  Eigen::Vector3d extrinsic_rotation_change = Eigen::Vector3d::Zero();
  Eigen::Vector3d extrinsic_translation_change = Eigen::Vector3d::Zero();
  /// Whether the solve estimated each (estimated, and the window's motion observes it), or held
  /// it where it was.
  bool time_offset_free = false;
  bool extrinsic_free = false;
};

struct Frame {
  std::size_t index = 0;  ///< 0-based position in the stream of frames
  double t = 0.0;         ///< seconds (the RGB-D observation's timestamp)
  std::string sensor_label;

  cv::Mat rgb;    ///< CV_8UC3, BGR; empty when the observation had no colour image
  cv::Mat depth;  ///< CV_32FC1, metres along the optical axis, 0 = invalid, registered to rgb
  CameraIntrinsics intrinsics;

  /// Where the sensors sit on the body (robot) frame, from the observations' sensorPose (io's
  /// SensorSync): the colour camera's optical frame (x right, y down, z forward) and the IMU's
  /// axes. A rawlog that leaves sensorPose at MRPT's default (identity) puts the body at the
  /// camera's MRPT depth frame (x forward, y left, z up): T_body_camera is then the pure axis
  /// change optical -> body, and T_body_imu identity (also when no IMU was seen).
  Eigen::Isometry3d T_body_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_body_imu = Eigen::Isometry3d::Identity();

  std::vector<ImuSample> imu;  ///< samples with t in (previous frame's t, t]
  std::vector<GnssFix> gnss;   ///< fixes with t in (previous frame's t, t]

  /// Perception (method.md sections 1-2), in pipeline order: detector boxes, one depth-threshold
  /// mask per detection, the tracks after this frame's update.
  std::vector<Detection> detections;
  /// True when the detector ran on this very frame; false in real-time mode when it was busy
  /// and `detections` are empty (the tracker's predictions then stand in for them).
  bool detections_fresh = false;
  std::vector<ObjectMask> object_masks;
  std::vector<Track> tracks;

  /// Visual front-end (method.md sections 3-4): the tracked features, the motion state of each
  /// tracked object seen with features, the rigid point sets of dynamic objects.
  std::vector<Feature> features;
  std::vector<ObjectMotionState> object_motions;
  std::vector<RigidSet> rigid_sets;

  /// Camera pose in the world, set by the stage that estimates it.
  std::optional<Eigen::Isometry3d> T_world_camera;
  /// World poses of the objects the estimator follows this frame (the runner writes one TUM
  /// trajectory per object id).
  std::vector<ObjectPose> object_poses;
  /// Set (possibly empty) by the ObjectStates stage: every object it follows, measured or
  /// predicted this frame. Outputs prefer these to object_poses when set.
  std::optional<std::vector<ObjectState>> object_states;
  /// Set by the estimator when this frame became a keyframe.
  std::optional<KeyframeRecord> keyframe;
};

}  // namespace dynslam::core
