#pragma once
// Reads the ROS 1 messages bag2rawlog converts into plain values and MRPT observations. Every
// function checks the message against its role and throws ConversionError naming the topic
// (and the bag message's stamp) when it cannot be used: a wrong type, an unreadable encoding.
#include "TopicMap.h"

#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <opencv2/core/mat.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rosbag {
class MessageInstance;
}

namespace dynslam::rawlog_tools::bag {

/// Header stamp in integer nanoseconds since the Unix epoch.
using Nanoseconds = int64_t;

/// A colour image as it came: `encoded` holds the compressed bytes of a CompressedImage (kept
/// byte for byte when images are stored externally), `bgr` the decoded pixels.
struct ColourMessage {
  Nanoseconds stamp = 0;
  cv::Mat bgr;
  std::vector<uint8_t> encoded;
  std::string extension;  ///< ".jpg" / ".png" for encoded bytes
};

struct DepthMessage {
  Nanoseconds stamp = 0;
  cv::Mat depth;  ///< CV_16UC1, 0 = invalid
  float rangeUnits = 0.001f;
};

struct CameraIntrinsics {
  PinholeIntrinsics k;
  int width = 0, height = 0;
  std::array<double, 5> distortion{};  ///< k1 k2 p1 p2 k3 (plumb_bob), zeros otherwise
};

struct Vector3Sample {
  Nanoseconds stamp = 0;
  std::array<double, 3> v{};
};

/// The ROS types each role accepts, for checking a bag's connections before converting.
std::vector<std::string> acceptedTypes(const std::string& role);

/// sensor_msgs/Image (any encoding cv_bridge turns into bgr8) or CompressedImage (jpeg/png).
ColourMessage readColour(const rosbag::MessageInstance& m);

/// sensor_msgs/Image 16UC1/mono16 (values * depthUnit = metres) or 32FC1 (metres; NaN and
/// values <= 0 become 0, values beyond 65535 * 1 mm too), or a CompressedImage in
/// image_transport's compressedDepth format (a 12-byte header, then a 16-bit PNG).
DepthMessage readDepth(const rosbag::MessageInstance& m, double depthUnit);

CameraIntrinsics readCameraInfo(const rosbag::MessageInstance& m);

/// An IMU observation with gyro and accelerometer (ros1bridge's fromROS), stamped with the
/// header's stamp; the orientation stays only when the message has one (covariance[0] != -1).
std::shared_ptr<mrpt::obs::CObservationIMU> readImu(const rosbag::MessageInstance& m,
                                                    const std::string& label);

/// linear_acceleration (accel) or angular_velocity (gyro) of a RealSense split IMU message.
Vector3Sample readAccel(const rosbag::MessageInstance& m);
Vector3Sample readGyro(const rosbag::MessageInstance& m);

/// A NavSatFix as a CObservationGPS holding a GGA message; nullptr when the message has no
/// fix (status -1) or non-finite coordinates (skipped; the caller counts them).
std::shared_ptr<mrpt::obs::CObservationGPS> readNavSatFix(const rosbag::MessageInstance& m,
                                                          const std::string& label);

/// An nmea_msgs/Sentence parsed by MRPT's NMEA parser (CGPSInterface::parse_NMEA: GGA, RMC,
/// GLL, VTG, GSA, ZDA), stamped with the header's stamp; nullptr for a sentence it does not
/// recognise or whose checksum fails (skipped; the caller counts them).
std::shared_ptr<mrpt::obs::CObservationGPS> readNmeaSentence(const rosbag::MessageInstance& m,
                                                             const std::string& label);

}  // namespace dynslam::rawlog_tools::bag
