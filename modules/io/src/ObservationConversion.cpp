#include "dynslam/io/ObservationConversion.h"

#include "dynslam/io/DepthRegistration.h"

#include <mrpt/core/Clock.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace dynslam::io {
namespace {

core::CameraIntrinsics intrinsicsOf(const mrpt::img::TCamera& cam) {
  core::CameraIntrinsics k;
  k.fx = cam.fx();
  k.fy = cam.fy();
  k.cx = cam.cx();
  k.cy = cam.cy();
  k.width = static_cast<int>(cam.ncols);
  k.height = static_cast<int>(cam.nrows);
  return k;
}

Eigen::Isometry3d toEigen(const mrpt::poses::CPose3D& p) {
  Eigen::Isometry3d T;
  T.matrix() = p.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>().asEigen();
  return T;
}

std::string describe(const mrpt::obs::CObservation& obs) {
  return std::string(obs.GetRuntimeClass()->className) + " '" + obs.sensorLabel +
         "' at t=" + std::to_string(mrpt::Clock::toDouble(obs.timestamp));
}

}  // namespace

void fillFrameFromRgbd(const mrpt::obs::CObservation3DRangeScan& obs, core::Frame& frame) {
  frame.t = mrpt::Clock::toDouble(obs.timestamp);
  frame.sensor_label = obs.sensorLabel;
  obs.load();  // externally stored images; a no-op for embedded ones
  struct Unload {
    const mrpt::obs::CObservation3DRangeScan& o;
    ~Unload() { o.unload(); }
  } unload{obs};

  if (!obs.hasRangeImage || obs.rangeImage.rows() == 0)
    throw ConversionError(describe(obs) + ": missing depth (field rangeImage is empty)");

  const auto depthK = intrinsicsOf(obs.cameraParams);
  cv::Mat raw(static_cast<int>(obs.rangeImage.rows()), static_cast<int>(obs.rangeImage.cols()),
              CV_16UC1, const_cast<uint16_t*>(obs.rangeImage.data()));
  cv::Mat depth;
  raw.convertTo(depth, CV_32FC1, obs.rangeUnits);
  if (!obs.range_is_depth) rangesToDepths(depth, depthK);

  // Depth optical frame (x right, y down, z forward) in MRPT's depth frame (+X forward).
  const mrpt::poses::CPose3D opticalInDepth(0, 0, 0, mrpt::DEG2RAD(-90.0), 0,
                                            mrpt::DEG2RAD(-90.0));
  if (obs.hasIntensityImage && !obs.intensityImage.isEmpty()) {
    frame.T_body_camera = toEigen(obs.sensorPose) * toEigen(obs.relativePoseIntensityWRTDepth);
    cv::Mat img = obs.intensityImage.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
    if (img.channels() == 1)
      cv::cvtColor(img, frame.rgb, cv::COLOR_GRAY2BGR);
    else
      frame.rgb = img.clone();
    frame.intrinsics = intrinsicsOf(obs.cameraParamsIntensity);
    if (frame.intrinsics.width != frame.rgb.cols || frame.intrinsics.height != frame.rgb.rows) {
      // Some writers leave ncols/nrows unset; the image itself is the authority.
      frame.intrinsics.width = frame.rgb.cols;
      frame.intrinsics.height = frame.rgb.rows;
    }
    // MRPT's test compares the poses only: a depth camera with other intrinsics at the same
    // place (7-Scenes: f 585 px against the colour camera's 525) still needs registering.
    const bool sameCamera = obs.doDepthAndIntensityCamerasCoincide() &&
                            depth.cols == frame.rgb.cols && depth.rows == frame.rgb.rows &&
                            depthK.fx == frame.intrinsics.fx && depthK.fy == frame.intrinsics.fy &&
                            depthK.cx == frame.intrinsics.cx && depthK.cy == frame.intrinsics.cy;
    if (sameCamera) {
      frame.depth = depth;
    } else {
      // Depth optical frame -> MRPT's depth frame (+X forward) -> colour optical frame.
      const Eigen::Isometry3d T_colour_depth =
          toEigen(obs.relativePoseIntensityWRTDepth).inverse() * toEigen(opticalInDepth);
      frame.depth = registerDepth(depth, depthK, frame.intrinsics, T_colour_depth);
    }
  } else {
    frame.T_body_camera = toEigen(obs.sensorPose) * toEigen(opticalInDepth);
    frame.rgb.release();
    frame.depth = depth;
    frame.intrinsics = depthK;
    frame.intrinsics.width = depth.cols;
    frame.intrinsics.height = depth.rows;
  }
}

std::optional<core::ImuSample> imuSampleFrom(const mrpt::obs::CObservationIMU& obs) {
  using namespace mrpt::obs;
  core::ImuSample s;
  s.t = mrpt::Clock::toDouble(obs.timestamp);
  const auto read = [&](TIMUDataIndex idx, const char* field) {
    const double v = obs.get(idx);
    if (!std::isfinite(v))
      throw ConversionError(describe(obs) + ": field " + field + " is not finite (" +
                            std::to_string(v) + ")");
    return v;
  };
  s.has_gyro = obs.has(IMU_WX) && obs.has(IMU_WY) && obs.has(IMU_WZ);
  s.has_acc = obs.has(IMU_X_ACC) && obs.has(IMU_Y_ACC) && obs.has(IMU_Z_ACC);
  if (s.has_gyro) s.gyro = {read(IMU_WX, "IMU_WX"), read(IMU_WY, "IMU_WY"), read(IMU_WZ, "IMU_WZ")};
  if (s.has_acc)
    s.acc = {read(IMU_X_ACC, "IMU_X_ACC"), read(IMU_Y_ACC, "IMU_Y_ACC"),
             read(IMU_Z_ACC, "IMU_Z_ACC")};
  if (!s.has_gyro && !s.has_acc) return std::nullopt;
  return s;
}

Eigen::Isometry3d imuPoseOnBody(const mrpt::obs::CObservationIMU& obs) {
  return toEigen(obs.sensorPose);
}

std::optional<core::GnssFix> gnssFixFrom(const mrpt::obs::CObservationGPS& obs) {
  using mrpt::obs::gnss::Message_NMEA_GGA;
  if (!obs.has_GGA_datum()) return std::nullopt;
  const auto& gga = obs.getMsgByClass<Message_NMEA_GGA>().fields;
  core::GnssFix f;
  f.t = mrpt::Clock::toDouble(obs.timestamp);
  f.latitude_deg = gga.latitude_degrees;
  f.longitude_deg = gga.longitude_degrees;
  f.altitude_m = gga.altitude_meters;
  f.fix_quality = gga.fix_quality;
  f.satellites = static_cast<int>(gga.satellitesUsed);
  f.hdop = gga.thereis_HDOP ? gga.HDOP : 0.0;
  if (!std::isfinite(f.latitude_deg) || !std::isfinite(f.longitude_deg) ||
      !std::isfinite(f.altitude_m))
    throw ConversionError(describe(obs) + ": GGA latitude/longitude/altitude not finite");
  return f;
}

}  // namespace dynslam::io
