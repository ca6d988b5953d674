#include "SimulationWriter.h"

#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/SensorLabels.h>

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>

namespace fs = std::filesystem;

namespace dynslam::rawlog_tools {
namespace {

std::ofstream openText(const fs::path& path, const char* header) {
  std::ofstream out(path);
  if (!out) throw ConversionError("cannot write '" + path.string() + "'");
  out << header << std::setprecision(17);
  return out;
}

std::string frameName(size_t index) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%06zu", index);
  return buf;
}

}  // namespace

SimulationWriter::SimulationWriter(const std::string& outDir, const sim::Sequence& sequence,
                                   SensorFaults faults, sim::CalibrationErrorOptions calibration)
    : sim_(sequence),
      dir_(outDir),
      start_time_(sequence.startTime()),
      rawlog_((fs::create_directories(outDir), (fs::path(outDir) / "sim.rawlog").string())),
      images_(ImageStorage::External, (fs::path(outDir) / "sim_Images").string()),
      T_body_imu_(sequence.T_body_imu()),
      faults_(faults),
      calibration_(calibration),
      believed_T_body_camera_(calibration_.believedCameraInBody(sequence.T_body_camera())) {
  fs::create_directories(fs::path(dir_) / "labels");
  groundtruth_ = openText(fs::path(dir_) / "groundtruth.tum",
                          "# camera (optical frame) pose in the world: t tx ty tz qx qy qz qw\n");
  objects_ = openText(fs::path(dir_) / "objects.txt", core::kObjectGroundTruthHeader);
  biases_ = openText(fs::path(dir_) / "imu_biases.txt",
                     "# true IMU biases: t gyro_bias_xyz (rad/s) acc_bias_xyz (m/s^2)\n");
  writeCalibrationTruth();
}

void SimulationWriter::writeCalibrationTruth() const {
  const fs::path path = fs::path(dir_) / "calibration.txt";
  std::ofstream out = openText(path,
                               "# [Calibration]: what the rawlog says against the truth. "
                               "t_imu = t_camera + time_offset_s;\n# camera_in_imu_*: the "
                               "camera (optical frame) in the IMU frame, a row-major 4x4 (the "
                               "estimator's camera_in_imu)\n");
  const auto matrix = [&](const char* name, const Eigen::Isometry3d& T) {
    out << name;
    const Eigen::Matrix4d M = (sim_.T_body_imu().inverse() * T).matrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out << ' ' << M(r, c);
    out << '\n';
  };
  out << "time_offset_s " << calibration_.time_offset_s << '\n'
      << "time_jitter_s " << calibration_.time_jitter_s << '\n';
  matrix("camera_in_imu_true", sim_.T_body_camera());
  matrix("camera_in_imu_believed", believed_T_body_camera_);
  const Eigen::AngleAxisd error(believed_T_body_camera_.rotation() *
                                sim_.T_body_camera().rotation().transpose());
  out << "rotation_error_deg " << error.angle() * 180 / M_PI << '\n'
      << "translation_error_m "
      << (believed_T_body_camera_.translation() - sim_.T_body_camera().translation()).norm()
      << '\n';
  if (!out) throw ConversionError("cannot write '" + path.string() + "'");
}

void SimulationWriter::writeSamplesUpTo(double t) {
  const auto& imu = sim_.imu();
  for (; next_imu_ < imu.size() && imu[next_imu_].t <= t; ++next_imu_) {
    const auto& m = imu[next_imu_];
    if (m.t >= faults_.imu_gap_start && m.t < faults_.imu_gap_start + faults_.imu_gap_duration)
      continue;
    const auto obs = makeImuObservation(mrpt::Clock::fromDouble(stamp(m.t)), kImuLabel,
                                        std::array<double, 3>{m.gyro.x(), m.gyro.y(), m.gyro.z()},
                                        std::array<double, 3>{m.acc.x(), m.acc.y(), m.acc.z()});
    setImuPoseOnBody(*obs, T_body_imu_);
    rawlog_.write(*obs);
    biases_ << stamp(m.t) << ' ' << m.gyro_bias.transpose() << ' ' << m.acc_bias.transpose()
            << '\n';
  }
  const auto& gnss = sim_.gnss();
  for (; next_gnss_ < gnss.size() && gnss[next_gnss_].t <= t; ++next_gnss_) {
    const auto& g = gnss[next_gnss_];
    rawlog_.write(*makeGgaObservation(
        mrpt::Clock::fromDouble(stamp(g.t)), kGpsLabel,
        {g.latitude_deg, g.longitude_deg, g.altitude_m, g.fix_quality, g.satellites, g.hdop}));
  }
}

void SimulationWriter::write(const sim::SimFrame& frame) {
  // The camera's stamp (CalibrationErrors.h); the rawlog stays in stamp order.
  const double cameraT = calibration_.cameraStamp(frame.t, frame.index);
  writeSamplesUpTo(cameraT);
  const auto& k = sim_.camera();
  const auto within = [&](long first, long count) {
    return first >= 0 && long(frame.index) >= first && long(frame.index) < first + count;
  };
  const cv::Mat colour = within(faults_.black_first, faults_.black_count)
                             ? cv::Mat::zeros(frame.image.rgb.size(), frame.image.rgb.type())
                             : frame.image.rgb;
  RgbdFrame rgbd = simulatedRgbdFrame(
      mrpt::Clock::fromDouble(stamp(cameraT)), frame.image.depth, sim_.maxRange(),
      {k.fx, k.fy, k.cx, k.cy}, images_.storePixels(colour, "colour_" + frameName(frame.index)),
      "simulated frame " + std::to_string(frame.index));
  if (within(faults_.no_depth_first, faults_.no_depth_count)) rgbd.depth.setTo(0);
  const auto obs = makeRgbdObservation(rgbd);
  setCameraPoseOnBody(*obs, believed_T_body_camera_);
  rawlog_.write(*obs);

  const std::string labels =
      (fs::path(dir_) / "labels" / (frameName(frame.index) + ".png")).string();
  if (!cv::imwrite(labels, frame.image.label))
    throw ConversionError("cannot write '" + labels + "'");
  // The pose at the instant the stamp names on the IMU clock; none outside the trajectory.
  const std::optional<Eigen::Isometry3d> truth =
      calibration_.changesStamps() ? sim_.cameraPoseAt(cameraT) : frame.T_world_camera;
  if (truth) core::appendTumLine(groundtruth_, {stamp(cameraT), *truth});
  for (const auto& o : frame.objects)
    core::writeObjectGroundTruthRow(objects_, sim::groundTruthRow(frame.index, stamp(cameraT), o));
}

void SimulationWriter::finish() {
  writeSamplesUpTo(INFINITY);
  rawlog_.close();
  for (auto* f : {&groundtruth_, &objects_, &biases_}) {
    f->flush();
    if (!*f) throw ConversionError("writing the ground truth files in '" + dir_ + "' failed");
  }
}

}  // namespace dynslam::rawlog_tools
