#pragma once
// Which bag topic becomes which observation ([bag2rawlog] section of the topic-map ini), read
// strictly: an unknown key is an error naming it. Topics left empty are not converted.
#include <mrpt/config/CLoadableOptions.h>

#include <Eigen/Geometry>

#include <optional>
#include <string>

namespace dynslam::rawlog_tools::bag {

inline constexpr const char* kSection = "bag2rawlog";

struct TopicMap : mrpt::config::CLoadableOptions {
  std::string rgb_topic;          ///< sensor_msgs/Image or sensor_msgs/CompressedImage
  std::string depth_topic;        ///< sensor_msgs/Image (16UC1, mono16, 32FC1) or compressedDepth
  std::string camera_info_topic;  ///< sensor_msgs/CameraInfo; else fx fy cx cy below
  double fx = 0, fy = 0, cx = 0, cy = 0;
  /// Depth not registered to colour (RealSense SDK recordings): the depth camera's CameraInfo
  /// and its optical frame in the colour optical frame (T_colour_depth, x y z qx qy qz qw).
  std::string depth_camera_info_topic;
  std::string depth_to_colour_pose;
  double depth_unit = 0.001;    ///< metres per unit of a 16-bit depth image
  double max_depth = 10.0;      ///< CObservation3DRangeScan::maxRange (m)
  double rgbd_max_dt = 0.02;    ///< colour/depth pairs further apart (s) are not paired
  std::string imu_topic;        ///< sensor_msgs/Imu with gyro and accelerometer
  std::string accel_topic;      ///< sensor_msgs/Imu, accelerometer only (RealSense)
  std::string gyro_topic;       ///< sensor_msgs/Imu, gyro only (RealSense)
  std::string gnss_topic;       ///< sensor_msgs/NavSatFix
  std::string nmea_topic;       ///< nmea_msgs/Sentence (raw NMEA 0183 receiver output)
  std::string camera_pose;      ///< T_body_optical "x y z qx qy qz qw"; empty: MRPT default
  std::string imu_pose;         ///< T_body_imu "x y z qx qy qz qw"; empty: identity
  std::string gnss_pose;        ///< antenna on the body "x y z qx qy qz qw"; empty: identity
  double reorder_window = 1.0;  ///< s; observations are sorted by stamp within this window

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;

  /// Throws ConversionError (naming `source` and the key) for inconsistent settings: nothing to
  /// convert, imu_topic together with accel/gyro topics, only one of accel/gyro, an RGB-D
  /// pair without intrinsics, a bad pose string or a non-positive tolerance.
  void validate(const std::string& source) const;

  bool hasRgbd() const { return !rgb_topic.empty(); }
  bool depthRegistered() const { return depth_camera_info_topic.empty(); }
  bool hasSplitImu() const { return !accel_topic.empty(); }
};

/// Parses "x y z qx qy qz qw" (TUM order); nullopt for an empty string. Throws ConversionError
/// naming `key` when it is not 7 finite numbers or the quaternion is not unit length.
std::optional<Eigen::Isometry3d> parsePose(const std::string& text, const std::string& key);

}  // namespace dynslam::rawlog_tools::bag
