#include "TopicMap.h"

#include <dynslam/rawlog_tools/ConversionError.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dynslam::rawlog_tools::bag {

void TopicMap::describe(core::OptionVisitor& v) {
  using core::Range;
  const Range pixels = Range::atLeast(0), positive = Range::above(0);
  v.key("rgb_topic", rgb_topic, "colour: sensor_msgs/Image or CompressedImage");
  v.key("depth_topic", depth_topic,
        "depth registered to colour: Image 16UC1/mono16 (depth_unit) or 32FC1 (m), or "
        "compressedDepth");
  v.key("camera_info_topic", camera_info_topic,
        "sensor_msgs/CameraInfo of the colour camera (else fx fy cx cy)");
  v.key("fx", fx, pixels, "colour focal length x (px), when there is no camera_info_topic");
  v.key("fy", fy, pixels, "colour focal length y (px)");
  v.key("cx", cx, pixels, "colour principal point x (px)");
  v.key("cy", cy, pixels, "colour principal point y (px)");
  v.key("depth_camera_info_topic", depth_camera_info_topic,
        "CameraInfo of a depth camera not registered to colour (RealSense SDK recordings; "
        "empty: registered)");
  v.key("depth_to_colour_pose", depth_to_colour_pose,
        "that depth optical frame in the colour optical frame (T_colour_depth): x y z qx qy qz "
        "qw");
  v.key("depth_unit", depth_unit, positive, "metres per unit of a 16-bit depth image");
  v.key("max_depth", max_depth, positive, "maxRange of the RGB-D observations (m)");
  v.key("rgbd_max_dt", rgbd_max_dt, positive, "largest colour-depth stamp difference paired (s)");
  v.key("imu_topic", imu_topic, "sensor_msgs/Imu with gyro and accelerometer");
  v.key("accel_topic", accel_topic,
        "sensor_msgs/Imu, accelerometer only (interpolated at gyro_topic's stamps)");
  v.key("gyro_topic", gyro_topic, "sensor_msgs/Imu, gyro only");
  v.key("gnss_topic", gnss_topic, "sensor_msgs/NavSatFix (written as a GGA message)");
  v.key("nmea_topic", nmea_topic,
        "nmea_msgs/Sentence: NMEA 0183 sentences parsed by MRPT (GGA, RMC, ...)");
  v.key("camera_pose", camera_pose,
        "colour optical frame on the body: x y z qx qy qz qw (empty: MRPT default)");
  v.key("imu_pose", imu_pose, "IMU axes on the body: x y z qx qy qz qw (empty: identity)");
  v.key("gnss_pose", gnss_pose, "GNSS antenna on the body: x y z qx qy qz qw (empty: identity)");
  v.key("reorder_window", reorder_window, Range::atLeast(0),
        "s: observations are written in stamp order within this window");
  v.requires("depth_to_colour_pose", !depth_to_colour_pose.empty(), "depth_camera_info_topic",
             !depth_camera_info_topic.empty());
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
  try {
    check();  // ranges and depth_to_colour_pose's need, for a map set in code
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
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
