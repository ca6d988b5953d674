#include "BagMessages.h"

#include "NmeaSentence.h"

#include <cv_bridge/cv_bridge.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/Timestamps.h>
#include <mrpt/hwdrivers/CGPSInterface.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/ros1bridge/gps.h>
#include <mrpt/ros1bridge/image.h>
#include <mrpt/ros1bridge/imu.h>
#include <mrpt/system/datetime.h>
#include <rosbag/message_instance.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/image_encodings.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstring>

namespace dynslam::rawlog_tools::bag {
namespace {

constexpr const char* kImage = "sensor_msgs/Image";
constexpr const char* kCompressed = "sensor_msgs/CompressedImage";

Nanoseconds nanoseconds(const ros::Time& t) {
  return static_cast<Nanoseconds>(t.sec) * 1000000000 + static_cast<Nanoseconds>(t.nsec);
}

std::string describe(const rosbag::MessageInstance& m) {
  return "topic " + m.getTopic() + " (" + m.getDataType() + ", bag time " +
         std::to_string(m.getTime().toSec()) + ")";
}

template <typename T>
boost::shared_ptr<T> instantiate(const rosbag::MessageInstance& m) {
  auto msg = m.instantiate<T>();
  if (!msg)
    throw ConversionError(describe(m) + ": expected " +
                          std::string(ros::message_traits::DataType<T>::value()));
  return msg;
}

std::string extensionOf(const std::vector<uint8_t>& bytes) {
  static const uint8_t png[] = {0x89, 'P', 'N', 'G'};
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), png, 4) == 0) return ".png";
  if (bytes.size() >= 2 && bytes[0] == 0xFF && bytes[1] == 0xD8) return ".jpg";
  return "";
}

}  // namespace

std::vector<std::string> acceptedTypes(const std::string& role) {
  if (role == "rgb_topic" || role == "depth_topic") return {kImage, kCompressed};
  if (role == "camera_info_topic" || role == "depth_camera_info_topic")
    return {"sensor_msgs/CameraInfo"};
  if (role == "gnss_topic") return {"sensor_msgs/NavSatFix"};
  if (role == "nmea_topic") return {"nmea_msgs/Sentence"};
  return {"sensor_msgs/Imu"};  // imu_topic, accel_topic, gyro_topic
}

ColourMessage readColour(const rosbag::MessageInstance& m) {
  ColourMessage out;
  if (m.getDataType() == kCompressed) {
    const auto msg = instantiate<sensor_msgs::CompressedImage>(m);
    out.stamp = nanoseconds(msg->header.stamp);
    out.encoded = msg->data;
    out.extension = extensionOf(out.encoded);
    if (out.extension.empty() || msg->format.find("compressedDepth") != std::string::npos)
      throw ConversionError(describe(m) + ": format '" + msg->format +
                            "' is not a JPEG or PNG colour image");
    out.bgr = cv::imdecode(out.encoded, cv::IMREAD_COLOR);
    if (out.bgr.empty()) throw ConversionError(describe(m) + ": cannot decode the image");
    return out;
  }
  const auto msg = instantiate<sensor_msgs::Image>(m);
  out.stamp = nanoseconds(msg->header.stamp);
  try {
    // ros1bridge converts through cv_bridge to BGR (rgb8, mono8, bayer, ... all work).
    out.bgr = mrpt::ros1bridge::fromROS(*msg).asCvMatRef().clone();
  } catch (const std::exception& e) {
    throw ConversionError(describe(m) + ": encoding '" + msg->encoding +
                          "' cannot be read as a colour image (" + e.what() + ")");
  }
  if (out.bgr.type() == CV_8UC1) cv::cvtColor(out.bgr, out.bgr, cv::COLOR_GRAY2BGR);
  if (out.bgr.type() != CV_8UC3)
    throw ConversionError(describe(m) + ": encoding '" + msg->encoding +
                          "' is not an 8-bit colour image");
  return out;
}

DepthMessage readDepth(const rosbag::MessageInstance& m, double depthUnit) {
  namespace enc = sensor_msgs::image_encodings;
  DepthMessage out;
  out.rangeUnits = static_cast<float>(depthUnit);
  if (m.getDataType() == kCompressed) {
    const auto msg = instantiate<sensor_msgs::CompressedImage>(m);
    out.stamp = nanoseconds(msg->header.stamp);
    // image_transport's compressedDepth: "16UC1; compressedDepth [png]" is a 12-byte
    // ConfigHeader followed by a 16-bit PNG; 32FC1 uses a quantised inverse depth, not read here.
    if (msg->format.rfind("16UC1", 0) != 0 && msg->format.rfind("mono16", 0) != 0)
      throw ConversionError(describe(m) + ": compressed depth format '" + msg->format +
                            "' is not supported (16UC1 compressedDepth PNG is)");
    const size_t offset = msg->data.size() > 12 && extensionOf(msg->data) != ".png" ? 12 : 0;
    const std::vector<uint8_t> png(msg->data.begin() + static_cast<long>(offset), msg->data.end());
    out.depth = cv::imdecode(png, cv::IMREAD_UNCHANGED);
    if (out.depth.type() != CV_16UC1)
      throw ConversionError(describe(m) + ": compressed depth is not a 16-bit PNG");
    return out;
  }
  const auto msg = instantiate<sensor_msgs::Image>(m);
  out.stamp = nanoseconds(msg->header.stamp);
  if (msg->encoding == enc::TYPE_16UC1 || msg->encoding == enc::MONO16) {
    out.depth = cv_bridge::toCvCopy(msg, enc::TYPE_16UC1)->image;
    return out;
  }
  if (msg->encoding == enc::TYPE_32FC1) {
    // Metres to millimetres: the rawlog stores depth as uint16 with rangeUnits.
    const cv::Mat metres = cv_bridge::toCvShare(msg, enc::TYPE_32FC1)->image;
    out.rangeUnits = 0.001f;
    out.depth.create(metres.size(), CV_16UC1);
    for (int r = 0; r < metres.rows; ++r) {
      const float* src = metres.ptr<float>(r);
      uint16_t* dst = out.depth.ptr<uint16_t>(r);
      for (int c = 0; c < metres.cols; ++c) {
        const double mm = std::round(static_cast<double>(src[c]) * 1000.0);
        dst[c] = (std::isfinite(mm) && mm > 0 && mm <= 65535.0) ? static_cast<uint16_t>(mm) : 0;
      }
    }
    return out;
  }
  throw ConversionError(describe(m) + ": depth encoding '" + msg->encoding +
                        "' is not supported (16UC1 / mono16 in depth_unit, 32FC1 in metres)");
}

CameraIntrinsics readCameraInfo(const rosbag::MessageInstance& m) {
  const auto msg = instantiate<sensor_msgs::CameraInfo>(m);
  CameraIntrinsics out;
  out.k = {msg->K[0], msg->K[4], msg->K[2], msg->K[5]};
  out.width = static_cast<int>(msg->width);
  out.height = static_cast<int>(msg->height);
  if (!(out.k.fx > 0 && out.k.fy > 0))
    throw ConversionError(describe(m) + ": K has no focal length (fx " + std::to_string(out.k.fx) +
                          ", fy " + std::to_string(out.k.fy) + ")");
  if (msg->distortion_model == "plumb_bob" || msg->distortion_model == "rational_polynomial")
    for (size_t i = 0; i < 5 && i < msg->D.size(); ++i) out.distortion[i] = msg->D[i];
  return out;
}

std::shared_ptr<mrpt::obs::CObservationIMU> readImu(const rosbag::MessageInstance& m,
                                                    const std::string& label) {
  const auto msg = instantiate<sensor_msgs::Imu>(m);
  auto obs = std::make_shared<mrpt::obs::CObservationIMU>();
  mrpt::ros1bridge::fromROS(*msg, *obs);
  // fromROS stamps with the current time and always sets the orientation.
  obs->timestamp = timeFromNanoseconds(nanoseconds(msg->header.stamp));
  obs->sensorLabel = label;
  if (msg->orientation_covariance[0] == -1.0)
    for (auto i : {mrpt::obs::IMU_ORI_QUAT_X, mrpt::obs::IMU_ORI_QUAT_Y, mrpt::obs::IMU_ORI_QUAT_Z,
                   mrpt::obs::IMU_ORI_QUAT_W})
      obs->dataIsPresent[i] = false;
  return obs;
}

Vector3Sample readAccel(const rosbag::MessageInstance& m) {
  const auto msg = instantiate<sensor_msgs::Imu>(m);
  const auto& a = msg->linear_acceleration;
  return {nanoseconds(msg->header.stamp), {a.x, a.y, a.z}};
}

Vector3Sample readGyro(const rosbag::MessageInstance& m) {
  const auto msg = instantiate<sensor_msgs::Imu>(m);
  const auto& w = msg->angular_velocity;
  return {nanoseconds(msg->header.stamp), {w.x, w.y, w.z}};
}

std::shared_ptr<mrpt::obs::CObservationGPS> readNavSatFix(const rosbag::MessageInstance& m,
                                                          const std::string& label) {
  const auto msg = instantiate<sensor_msgs::NavSatFix>(m);
  if (msg->status.status == sensor_msgs::NavSatStatus::STATUS_NO_FIX ||
      !std::isfinite(msg->latitude) || !std::isfinite(msg->longitude) ||
      !std::isfinite(msg->altitude))
    return nullptr;
  auto obs = std::make_shared<mrpt::obs::CObservationGPS>();
  // fromROS fills the GGA position and fix quality; it leaves the stamps and the GGA UTC time
  // unset (the observation gets the current time), so those are set here from the header.
  mrpt::ros1bridge::fromROS(*msg, *obs);
  if (!obs->has_GGA_datum()) throw ConversionError(describe(m) + ": fromROS gave no GGA message");
  obs->timestamp = timeFromNanoseconds(nanoseconds(msg->header.stamp));
  obs->originalReceivedTimestamp = obs->timestamp;
  obs->sensorLabel = label;
  auto& gga = obs->getMsgByClass<mrpt::obs::gnss::Message_NMEA_GGA>().fields;
  mrpt::system::TTimeParts parts;
  mrpt::system::timestampToParts(obs->timestamp, parts);
  gga.UTCTime.hour = static_cast<uint8_t>(parts.hour);
  gga.UTCTime.minute = static_cast<uint8_t>(parts.minute);
  gga.UTCTime.sec = parts.second;
  return obs;
}

std::shared_ptr<mrpt::obs::CObservationGPS> readNmeaSentence(const rosbag::MessageInstance& m,
                                                             const std::string& label) {
  const auto msg = instantiate<nmea_msgs::Sentence>(m);
  auto obs = std::make_shared<mrpt::obs::CObservationGPS>();
  std::string line = msg->sentence;
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.pop_back();
  if (!mrpt::hwdrivers::CGPSInterface::parse_NMEA(line, *obs)) return nullptr;
  // The parser stamps with the current time (a sentence alone has no date).
  obs->timestamp = timeFromNanoseconds(nanoseconds(msg->header.stamp));
  obs->originalReceivedTimestamp = obs->timestamp;
  obs->sensorLabel = label;
  return obs;
}

}  // namespace dynslam::rawlog_tools::bag
