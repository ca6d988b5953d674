#include "dynslam/rawlog_tools/ObservationBuilders.h"

#include "dynslam/rawlog_tools/ConversionError.h"
#include "dynslam/rawlog_tools/SensorLabels.h"

#include <mrpt/img/CImage.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/datetime.h>

#include <cstring>

namespace dynslam::rawlog_tools {
namespace {

mrpt::img::TCamera makeCamera(const PinholeIntrinsics& k, int width, int height) {
  mrpt::img::TCamera camera;
  camera.ncols = static_cast<uint32_t>(width);
  camera.nrows = static_cast<uint32_t>(height);
  camera.setIntrinsicParamsFromValues(k.fx, k.fy, k.cx, k.cy);
  camera.dist.fill(0.0);  // the datasets ship undistorted (or distortion-free) images
  return camera;
}

void copyDepth(const cv::Mat& depth, const std::optional<uint16_t>& invalidValue,
               mrpt::math::CMatrix_u16& target) {
  for (int r = 0; r < depth.rows; ++r) {
    const uint16_t* src = depth.ptr<uint16_t>(r);
    uint16_t* dst = &target(r, 0);
    if (!invalidValue) {
      std::memcpy(dst, src, sizeof(uint16_t) * static_cast<size_t>(depth.cols));
      continue;
    }
    for (int c = 0; c < depth.cols; ++c) dst[c] = (src[c] == *invalidValue) ? 0 : src[c];
  }
}

mrpt::poses::CPose3D toPose(const Eigen::Isometry3d& T) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = T.matrix()(r, c);
  return mrpt::poses::CPose3D(m);
}

}  // namespace

void setCameraPoseOnBody(mrpt::obs::CObservation3DRangeScan& obs,
                         const Eigen::Isometry3d& T_body_optical) {
  // T_body_depthFrame = T_body_optical * T_optical_depthFrame.
  obs.sensorPose = toPose(T_body_optical) + (-obs.relativePoseIntensityWRTDepth);
}

void setImuPoseOnBody(mrpt::obs::CObservationIMU& obs, const Eigen::Isometry3d& T_body_imu) {
  obs.sensorPose = toPose(T_body_imu);
}

RgbdFrame simulatedRgbdFrame(mrpt::Clock::time_point timestamp, const cv::Mat& depthMetres,
                             double maxRange, const PinholeIntrinsics& intrinsics,
                             StoredColourImage colour, std::string sourceName) {
  RgbdFrame rgbd;
  rgbd.timestamp = timestamp;
  rgbd.sensorLabel = kRgbdLabel;
  depthMetres.convertTo(rgbd.depth, CV_16UC1, 1000.0);  // mm; 0 stays invalid
  rgbd.rangeUnits = 0.001f;
  rgbd.maxRange = static_cast<float>(maxRange);
  rgbd.intrinsics = intrinsics;
  rgbd.colour = std::move(colour);
  rgbd.depthSourceName = std::move(sourceName);
  return rgbd;
}

std::shared_ptr<mrpt::obs::CObservation3DRangeScan> makeRgbdObservation(const RgbdFrame& frame) {
  if (frame.depth.empty() || frame.depth.type() != CV_16UC1)
    throw ConversionError("depth image " + frame.depthSourceName + " is not 16-bit single-channel");
  if (frame.colour.width != frame.depth.cols || frame.colour.height != frame.depth.rows)
    throw ConversionError(
        "depth image " + frame.depthSourceName + " is " + std::to_string(frame.depth.cols) + "x" +
        std::to_string(frame.depth.rows) + " but its colour image is " +
        std::to_string(frame.colour.width) + "x" + std::to_string(frame.colour.height) +
        " (registered frames must have the same size)");

  auto obs = std::make_shared<mrpt::obs::CObservation3DRangeScan>();
  obs->timestamp = frame.timestamp;
  obs->sensorLabel = frame.sensorLabel;

  obs->hasRangeImage = true;
  obs->rangeImage_setSize(frame.depth.rows, frame.depth.cols);
  copyDepth(frame.depth, frame.invalidDepthValue, obs->rangeImage);
  obs->rangeUnits = frame.rangeUnits;
  obs->range_is_depth = true;
  obs->maxRange = frame.maxRange;
  obs->cameraParams = makeCamera(frame.intrinsics, frame.depth.cols, frame.depth.rows);

  obs->hasIntensityImage = true;
  obs->intensityImageChannel = mrpt::obs::CObservation3DRangeScan::CH_VISIBLE;
  if (!frame.colour.externalName.empty())
    obs->intensityImage.setExternalStorage(frame.colour.externalName);
  else
    obs->intensityImage = mrpt::img::CImage(frame.colour.pixels, mrpt::img::DEEP_COPY);
  obs->cameraParamsIntensity = makeCamera(frame.colourIntrinsics.value_or(frame.intrinsics),
                                          frame.colour.width, frame.colour.height);
  // relativePoseIntensityWRTDepth keeps its default: the cameras share centre and axes.
  return obs;
}

std::shared_ptr<mrpt::obs::CObservationIMU> makeImuObservation(
    mrpt::Clock::time_point timestamp, const std::string& sensorLabel,
    const std::optional<std::array<double, 3>>& gyro,
    const std::optional<std::array<double, 3>>& acc) {
  using namespace mrpt::obs;
  auto obs = std::make_shared<CObservationIMU>();
  obs->timestamp = timestamp;
  obs->sensorLabel = sensorLabel;
  if (gyro) {
    obs->set(IMU_WX, (*gyro)[0]);
    obs->set(IMU_WY, (*gyro)[1]);
    obs->set(IMU_WZ, (*gyro)[2]);
  }
  if (acc) {
    obs->set(IMU_X_ACC, (*acc)[0]);
    obs->set(IMU_Y_ACC, (*acc)[1]);
    obs->set(IMU_Z_ACC, (*acc)[2]);
  }
  return obs;
}

std::shared_ptr<mrpt::obs::CObservationGPS> makeGgaObservation(mrpt::Clock::time_point timestamp,
                                                               const std::string& sensorLabel,
                                                               const GgaFix& fix) {
  auto obs = std::make_shared<mrpt::obs::CObservationGPS>();
  obs->timestamp = timestamp;
  obs->sensorLabel = sensorLabel;
  mrpt::obs::gnss::Message_NMEA_GGA gga;
  auto& f = gga.fields;
  f.latitude_degrees = fix.latitude_deg;
  f.longitude_degrees = fix.longitude_deg;
  f.altitude_meters = fix.altitude_m;
  f.fix_quality = static_cast<uint8_t>(fix.fix_quality);
  f.satellitesUsed = static_cast<uint32_t>(fix.satellites);
  f.thereis_HDOP = true;
  f.HDOP = static_cast<float>(fix.hdop);
  mrpt::system::TTimeParts parts;
  mrpt::system::timestampToParts(timestamp, parts);
  f.UTCTime.hour = static_cast<uint8_t>(parts.hour);
  f.UTCTime.minute = static_cast<uint8_t>(parts.minute);
  f.UTCTime.sec = parts.second;
  obs->setMsg(gga);
  obs->originalReceivedTimestamp = timestamp;
  return obs;
}

}  // namespace dynslam::rawlog_tools
