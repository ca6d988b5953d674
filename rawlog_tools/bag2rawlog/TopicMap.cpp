#include "TopicMap.h"

#include <dynslam/core/Config.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <mrpt/config/CConfigFileBase.h>

#include <cmath>
#include <sstream>

namespace dynslam::rawlog_tools::bag {

using core::writeKey;

void TopicMap::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) {
  auto str = [&](std::string& v, const char* key) { v = c.read_string(s, key, v); };
  auto num = [&](double& v, const char* key) { v = c.read_double(s, key, v); };
  str(rgb_topic, "rgb_topic");
  str(depth_topic, "depth_topic");
  str(camera_info_topic, "camera_info_topic");
  num(fx, "fx");
  num(fy, "fy");
  num(cx, "cx");
  num(cy, "cy");
  str(depth_camera_info_topic, "depth_camera_info_topic");
  str(depth_to_colour_pose, "depth_to_colour_pose");
  num(depth_unit, "depth_unit");
  num(max_depth, "max_depth");
  num(rgbd_max_dt, "rgbd_max_dt");
  str(imu_topic, "imu_topic");
  str(accel_topic, "accel_topic");
  str(gyro_topic, "gyro_topic");
  str(gnss_topic, "gnss_topic");
  str(nmea_topic, "nmea_topic");
  str(camera_pose, "camera_pose");
  str(imu_pose, "imu_pose");
  str(gnss_pose, "gnss_pose");
  num(reorder_window, "reorder_window");
}

void TopicMap::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const {
  writeKey(c, s, "rgb_topic", rgb_topic, "colour: sensor_msgs/Image or CompressedImage");
  writeKey(c, s, "depth_topic", depth_topic,
           "depth registered to colour: Image 16UC1/mono16 (depth_unit) or 32FC1 (m)");
  writeKey(c, s, "camera_info_topic", camera_info_topic,
           "sensor_msgs/CameraInfo of the colour camera (else fx fy cx cy)");
  writeKey(c, s, "fx", fx, "colour focal length x (px), when there is no camera_info_topic");
  writeKey(c, s, "fy", fy, "colour focal length y (px)");
  writeKey(c, s, "cx", cx, "colour principal point x (px)");
  writeKey(c, s, "cy", cy, "colour principal point y (px)");
  writeKey(c, s, "depth_camera_info_topic", depth_camera_info_topic,
           "CameraInfo of a depth camera not registered to colour (empty: registered)");
  writeKey(c, s, "depth_to_colour_pose", depth_to_colour_pose,
           "that depth optical frame in the colour optical frame: x y z qx qy qz qw");
  writeKey(c, s, "depth_unit", depth_unit, "metres per unit of a 16-bit depth image");
  writeKey(c, s, "max_depth", max_depth, "maxRange of the RGB-D observations (m)");
  writeKey(c, s, "rgbd_max_dt", rgbd_max_dt, "largest colour-depth stamp difference paired (s)");
  writeKey(c, s, "imu_topic", imu_topic, "sensor_msgs/Imu with gyro and accelerometer");
  writeKey(c, s, "accel_topic", accel_topic,
           "sensor_msgs/Imu, accelerometer only (interpolated at gyro_topic's stamps)");
  writeKey(c, s, "gyro_topic", gyro_topic, "sensor_msgs/Imu, gyro only");
  writeKey(c, s, "gnss_topic", gnss_topic, "sensor_msgs/NavSatFix (written as a GGA message)");
  writeKey(c, s, "nmea_topic", nmea_topic,
           "nmea_msgs/Sentence: NMEA 0183 sentences parsed by MRPT (GGA, RMC, ...)");
  writeKey(c, s, "camera_pose", camera_pose,
           "colour optical frame on the body: x y z qx qy qz qw (empty: MRPT default)");
  writeKey(c, s, "imu_pose", imu_pose, "IMU axes on the body: x y z qx qy qz qw");
  writeKey(c, s, "gnss_pose", gnss_pose, "GNSS antenna on the body: x y z qx qy qz qw");
  writeKey(c, s, "reorder_window", reorder_window,
           "s: observations are written in stamp order within this window");
}

void TopicMap::validate(const std::string& source) const {
  const std::string where = source + " [" + kSection + "] ";
  auto fail = [&](const std::string& what) { throw ConversionError(where + what); };
  if (rgb_topic.empty() && depth_topic.empty() && imu_topic.empty() && accel_topic.empty() &&
      gyro_topic.empty() && gnss_topic.empty() && nmea_topic.empty())
    fail("names no topic to convert (rgb_topic, depth_topic, imu_topic, accel_topic, " +
         std::string("gyro_topic, gnss_topic, nmea_topic)"));
  if (rgb_topic.empty() != depth_topic.empty())
    fail("rgb_topic and depth_topic go together (RGB-D observations need both)");
  if (!imu_topic.empty() && (!accel_topic.empty() || !gyro_topic.empty()))
    fail("imu_topic excludes accel_topic / gyro_topic");
  if (accel_topic.empty() != gyro_topic.empty())
    fail("accel_topic and gyro_topic go together (one IMU observation per gyro sample)");
  if (hasRgbd() && camera_info_topic.empty() && (fx <= 0 || fy <= 0 || cx <= 0 || cy <= 0))
    fail("needs camera_info_topic or fx, fy, cx, cy > 0 for the colour camera");
  if (!depth_to_colour_pose.empty() && depth_camera_info_topic.empty())
    fail("depth_to_colour_pose needs depth_camera_info_topic (the depth camera's intrinsics)");
  if (!(rgbd_max_dt > 0)) fail("rgbd_max_dt must be > 0");
  if (!(depth_unit > 0)) fail("depth_unit must be > 0");
  if (!(max_depth > 0)) fail("max_depth must be > 0");
  if (!(reorder_window >= 0)) fail("reorder_window must be >= 0");
  parsePose(camera_pose, where + "camera_pose");
  parsePose(imu_pose, where + "imu_pose");
  parsePose(gnss_pose, where + "gnss_pose");
  parsePose(depth_to_colour_pose, where + "depth_to_colour_pose");
}

std::optional<Eigen::Isometry3d> parsePose(const std::string& text, const std::string& key) {
  if (text.find_first_not_of(" \t") == std::string::npos) return std::nullopt;
  std::istringstream in(text);
  double v[7];
  for (double& x : v)
    if (!(in >> x) || !std::isfinite(x))
      throw ConversionError(key + " = '" + text + "' is not 7 numbers x y z qx qy qz qw");
  std::string rest;
  if (in >> rest)
    throw ConversionError(key + " = '" + text + "' has more than 7 numbers (x y z qx qy qz qw)");
  const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
  if (std::abs(q.norm() - 1.0) > 1e-3)
    throw ConversionError(key + ": quaternion (qx qy qz qw) has norm " + std::to_string(q.norm()));
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  return T;
}

}  // namespace dynslam::rawlog_tools::bag
