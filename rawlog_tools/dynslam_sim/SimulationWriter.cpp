#include "SimulationWriter.h"

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

SimulationWriter::SimulationWriter(const std::string& outDir, const sim::Sequence& sequence)
    : sim_(sequence),
      dir_(outDir),
      start_time_(sequence.startTime()),
      rawlog_((fs::create_directories(outDir), (fs::path(outDir) / "sim.rawlog").string())),
      images_(ImageStorage::External, (fs::path(outDir) / "sim_Images").string()) {
  fs::create_directories(fs::path(dir_) / "labels");
  groundtruth_ = openText(fs::path(dir_) / "groundtruth.tum",
                          "# camera (optical frame) pose in the world: t tx ty tz qx qy qz qw\n");
  objects_ = openText(
      fs::path(dir_) / "objects.txt",
      "# dynslam-sim object ground truth: one line per frame and object at least partly in view\n"
      "# frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels "
      "visible_fraction\n"
      "# pose: the object's rigid core in the world (a person's torso centre, a car's body\n"
      "# centre); box: amodal, in pixels, clipped to the image (an object hidden behind a wall\n"
      "# is listed with 0 visible pixels); visible_fraction: visible pixels / pixels it would\n"
      "# cover with nothing in front of it; labels/NNNNNN.png holds `id` at the visible pixels.\n"
      "# class: person | car; moving: 1 when it moves at t (0: standing person, parked car).\n");
  biases_ = openText(fs::path(dir_) / "imu_biases.txt",
                     "# true IMU biases: t gyro_bias_xyz (rad/s) acc_bias_xyz (m/s^2)\n");
}

void SimulationWriter::writeSamplesUpTo(double t) {
  const auto& imu = sim_.imu();
  for (; next_imu_ < imu.size() && imu[next_imu_].t <= t; ++next_imu_) {
    const auto& m = imu[next_imu_];
    rawlog_.write(*makeImuObservation(mrpt::Clock::fromDouble(stamp(m.t)), kImuLabel,
                                      std::array<double, 3>{m.gyro.x(), m.gyro.y(), m.gyro.z()},
                                      std::array<double, 3>{m.acc.x(), m.acc.y(), m.acc.z()}));
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
  writeSamplesUpTo(frame.t);
  const auto& k = sim_.camera();
  RgbdFrame rgbd;
  rgbd.timestamp = mrpt::Clock::fromDouble(stamp(frame.t));
  rgbd.sensorLabel = kRgbdLabel;
  frame.image.depth.convertTo(rgbd.depth, CV_16UC1, 1000.0);  // mm; 0 stays invalid
  rgbd.rangeUnits = 0.001f;
  rgbd.maxRange = static_cast<float>(sim_.maxRange());
  rgbd.intrinsics = {k.fx, k.fy, k.cx, k.cy};
  rgbd.colour = images_.storePixels(frame.image.rgb, "colour_" + frameName(frame.index));
  rgbd.depthSourceName = "simulated frame " + std::to_string(frame.index);
  rawlog_.write(*makeRgbdObservation(rgbd));

  const std::string labels =
      (fs::path(dir_) / "labels" / (frameName(frame.index) + ".png")).string();
  if (!cv::imwrite(labels, frame.image.label))
    throw ConversionError("cannot write '" + labels + "'");
  core::appendTumLine(groundtruth_, {stamp(frame.t), frame.T_world_camera});
  for (const auto& o : frame.objects) {
    const Eigen::Quaterniond q(o.T_world_object.rotation());
    const Eigen::Vector3d p = o.T_world_object.translation();
    objects_ << frame.index << ' ' << stamp(frame.t) << ' ' << o.id << ' ' << o.category << ' '
             << (o.moving ? 1 : 0) << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x()
             << ' ' << q.y() << ' ' << q.z() << ' ' << q.w() << ' ' << o.box.x << ' ' << o.box.y
             << ' ' << o.box.width << ' ' << o.box.height << ' ' << o.visible_pixels << ' '
             << o.visible_fraction << '\n';
  }
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
