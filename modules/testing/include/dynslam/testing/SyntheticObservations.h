#pragma once
// Small hand-made MRPT observations and rawlogs for tests (kept out of non-test headers: it
// pulls in MRPT's observation headers).
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/serialization/CArchive.h>

#include <dynslam/testing/SyntheticRoom.h>

#include <opencv2/core.hpp>

#include <cstring>
#include <string>
#include <vector>

namespace dynslam::testing {

/// A w x h RGB-D observation, fx = fy = 500, principal point at the centre; depth in mm is
/// 1000 + 10 * (u + v) (so every pixel is distinct) and colour a noisy ramp.
inline mrpt::obs::CObservation3DRangeScan::Ptr makeScan(double t, int w = 64, int h = 48,
                                                        const std::string& label = "RGBD") {
  auto obs = mrpt::obs::CObservation3DRangeScan::Create();
  obs->timestamp = mrpt::Clock::fromDouble(t);
  obs->sensorLabel = label;
  obs->hasRangeImage = true;
  obs->rangeUnits = 0.001f;
  obs->rangeImage.resize(h, w);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) obs->rangeImage(v, u) = static_cast<uint16_t>(1000 + 10 * (u + v));
  cv::Mat rgb(h, w, CV_8UC3);
  cv::randu(rgb, 0, 255);
  obs->hasIntensityImage = true;
  obs->intensityImage = mrpt::img::CImage(rgb, mrpt::img::DEEP_COPY);
  obs->cameraParams.ncols = obs->cameraParamsIntensity.ncols = w;
  obs->cameraParams.nrows = obs->cameraParamsIntensity.nrows = h;
  obs->cameraParams.setIntrinsicParamsFromValues(500, 500, w / 2.0, h / 2.0);
  obs->cameraParamsIntensity.setIntrinsicParamsFromValues(500, 500, w / 2.0, h / 2.0);
  return obs;
}

inline mrpt::obs::CObservationIMU::Ptr makeImu(double t, double gz = 0.1, double az = 9.81,
                                               bool with_gyro = true) {
  auto obs = mrpt::obs::CObservationIMU::Create();
  obs->timestamp = mrpt::Clock::fromDouble(t);
  obs->sensorLabel = "IMU";
  obs->set(mrpt::obs::IMU_X_ACC, 0.0);
  obs->set(mrpt::obs::IMU_Y_ACC, 0.0);
  obs->set(mrpt::obs::IMU_Z_ACC, az);
  if (with_gyro) {
    obs->set(mrpt::obs::IMU_WX, 0.0);
    obs->set(mrpt::obs::IMU_WY, 0.0);
    obs->set(mrpt::obs::IMU_WZ, gz);
  }
  return obs;
}

inline mrpt::obs::CObservationGPS::Ptr makeGga(double t, double lat, double lon, double alt,
                                               int quality = 1) {
  auto obs = mrpt::obs::CObservationGPS::Create();
  obs->timestamp = mrpt::Clock::fromDouble(t);
  obs->sensorLabel = "GPS";
  mrpt::obs::gnss::Message_NMEA_GGA gga;
  gga.fields.latitude_degrees = lat;
  gga.fields.longitude_degrees = lon;
  gga.fields.altitude_meters = alt;
  gga.fields.fix_quality = static_cast<uint8_t>(quality);
  gga.fields.satellitesUsed = 9;
  obs->setMsg(gga);
  return obs;
}

/// The synthetic room (SyntheticRoom.h) seen from T_world_camera as a Kinect-like observation:
/// depth in mm (rangeUnits 0.001), colour embedded.
inline mrpt::obs::CObservation3DRangeScan::Ptr makeRoomScan(
    double t, const Eigen::Isometry3d& T_world_camera,
    const core::CameraIntrinsics& k = vgaCamera()) {
  cv::Mat rgb, depth, depthMm;
  renderRoom(T_world_camera, k, rgb, depth);
  depth.convertTo(depthMm, CV_16UC1, 1000.0);
  auto obs = makeScan(t, k.width, k.height);
  std::memcpy(obs->rangeImage.data(), depthMm.data, depthMm.total() * sizeof(uint16_t));
  obs->intensityImage = mrpt::img::CImage(rgb, mrpt::img::DEEP_COPY);
  obs->cameraParams.setIntrinsicParamsFromValues(k.fx, k.fy, k.cx, k.cy);
  obs->cameraParamsIntensity.setIntrinsicParamsFromValues(k.fx, k.fy, k.cx, k.cy);
  return obs;
}

/// Writes `objects` (observations, sensory frames, actions) as a gzip rawlog.
inline void writeRawlog(const std::string& path,
                        const std::vector<mrpt::serialization::CSerializable::Ptr>& objects) {
  mrpt::io::CFileGZOutputStream f(path);
  auto out = mrpt::serialization::archiveFrom(f);
  for (const auto& o : objects) out << *o;
}

}  // namespace dynslam::testing
