#pragma once
// Which bag topic becomes which observation ([bag2rawlog] section of the topic-map ini), read
// strictly: an unknown key is an error naming it. Topics left empty are not converted.
// Keys, ranges, meanings: describe() in TopicMap.cpp; `bag2rawlog --print-topics-template`.
#include <dynslam/core/Options.h>

#include <Eigen/Geometry>

#include <optional>
#include <string>

namespace dynslam::rawlog_tools::bag {

inline constexpr const char* kSection = "bag2rawlog";

struct TopicMap : core::Options {
  std::string rgb_topic;
  std::string depth_topic;
  std::string camera_info_topic;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::string depth_camera_info_topic;
  std::string depth_to_colour_pose;
  double depth_unit = 0.001;
  double max_depth = 10.0;
  double rgbd_max_dt = 0.02;
  std::string imu_topic;
  std::string accel_topic;
  std::string gyro_topic;
  std::string gnss_topic;
  std::string nmea_topic;
  std::string camera_pose;
  std::string imu_pose;
  std::string gnss_pose;
  double reorder_window = 1.0;

  void describe(core::OptionVisitor& v) override;

  /// Throws ConversionError (naming `source` and the key) for inconsistent settings: nothing to
  /// convert, imu_topic together with accel/gyro topics, only one of accel/gyro, an RGB-D
  /// pair without intrinsics, a bad pose string, or (for a map set in code) a value out of its
  /// range.
  void validate(const std::string& source) const;

  bool hasRgbd() const { return !rgb_topic.empty(); }
  bool depthRegistered() const { return depth_camera_info_topic.empty(); }
  bool hasSplitImu() const { return !accel_topic.empty(); }
};

/// Parses "x y z qx qy qz qw" (TUM order); nullopt for an empty string. Throws ConversionError
/// naming `key` when it is not 7 finite numbers or the quaternion is not unit length.
std::optional<Eigen::Isometry3d> parsePose(const std::string& text, const std::string& key);

}  // namespace dynslam::rawlog_tools::bag
