#pragma once
// Builds the MRPT observations the converters write. MRPT types are only forward-declared
// here; include <mrpt/obs/CObservation3DRangeScan.h> / <mrpt/obs/CObservationIMU.h> where
// their fields are used.
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <mrpt/core/Clock.h>

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace mrpt::obs {
class CObservation3DRangeScan;
class CObservationIMU;
class CObservationGPS;
}  // namespace mrpt::obs

namespace dynslam::rawlog_tools {

struct PinholeIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

/// One registered colour + depth frame.
struct RgbdFrame {
  mrpt::Clock::time_point timestamp;
  std::string sensorLabel;
  /// Raw depth, CV_16UC1, 0 = invalid; metres = value * rangeUnits.
  cv::Mat depth;
  /// Raw depth value that also means "invalid" in the source (7-Scenes: 65535); written as 0.
  std::optional<uint16_t> invalidDepthValue;
  float rangeUnits = 0.001f;
  /// Depth beyond this is not trusted by MRPT consumers (CObservation3DRangeScan::maxRange).
  float maxRange = 10.0f;
  /// The depth camera's; the colour camera's too unless colourIntrinsics is given.
  PinholeIntrinsics intrinsics;
  /// The colour camera's when they differ from the depth camera's (same optical centre and
  /// axes, e.g. 7-Scenes: colour f = 525 px, depth f = 585 px): readers then register the
  /// depth to the colour image (io::fillFrameFromRgbd).
  std::optional<PinholeIntrinsics> colourIntrinsics;
  StoredColourImage colour;
  /// Names the depth source in error messages (e.g. the PNG path).
  std::string depthSourceName;
};

/// A simulated frame as the converters store one (sensor label RGBD): depth given in metres
/// (CV_32FC1, 0 = none) as uint16 millimetres, one pinhole camera for both images.
RgbdFrame simulatedRgbdFrame(mrpt::Clock::time_point timestamp, const cv::Mat& depthMetres,
                             double maxRange, const PinholeIntrinsics& intrinsics,
                             StoredColourImage colour, std::string sourceName);

/// range_is_depth = true, hasRangeImage = hasIntensityImage = true, cameraParams and
/// cameraParamsIntensity carry the depth and the colour intrinsics (the same unless
/// colourIntrinsics is set) and their image sizes; relativePoseIntensityWRTDepth keeps MRPT's
/// default (the cameras share their optical centre and axes).
/// Throws ConversionError when depth is not CV_16UC1 or its size differs from the colour image.
std::shared_ptr<mrpt::obs::CObservation3DRangeScan> makeRgbdObservation(const RgbdFrame& frame);

/// Records where the colour camera sits on the robot, the MRPT way: sensorPose is the pose of
/// the depth sensor's own frame (+X forward, +Y left, +Z up) on the robot, and the colour
/// camera's optical frame (x right, y down, z forward) is relativePoseIntensityWRTDepth from it.
/// So sensorPose = T_body_optical * relativePoseIntensityWRTDepth^-1 (with MRPT's default
/// relative pose, exactly the identity for a camera looking along the body's x axis).
void setCameraPoseOnBody(mrpt::obs::CObservation3DRangeScan& obs,
                         const Eigen::Isometry3d& T_body_optical);

/// sensorPose of an IMU observation: the IMU's axes on the robot (body) frame.
void setImuPoseOnBody(mrpt::obs::CObservationIMU& obs, const Eigen::Isometry3d& T_body_imu);

/// An IMU observation with only the given groups set: has(IMU_WX) is false without gyro.
/// gyro in rad/s (IMU_WX..WZ), acc in m/s^2 (IMU_X_ACC..Z_ACC); sensorPose stays identity.
std::shared_ptr<mrpt::obs::CObservationIMU> makeImuObservation(
    mrpt::Clock::time_point timestamp, const std::string& sensorLabel,
    const std::optional<std::array<double, 3>>& gyro,
    const std::optional<std::array<double, 3>>& acc);

/// A GNSS fix as an NMEA GGA message (the form MRPT's GNSS grabbers store): latitude and
/// longitude in degrees, altitude in metres, GGA fix quality, satellites in use and HDOP. The
/// GGA UTC time field is set from the timestamp.
struct GgaFix {
  double latitude_deg = 0, longitude_deg = 0, altitude_m = 0;
  int fix_quality = 1, satellites = 0;
  double hdop = 0;
};
std::shared_ptr<mrpt::obs::CObservationGPS> makeGgaObservation(mrpt::Clock::time_point timestamp,
                                                               const std::string& sensorLabel,
                                                               const GgaFix& fix);

}  // namespace dynslam::rawlog_tools
