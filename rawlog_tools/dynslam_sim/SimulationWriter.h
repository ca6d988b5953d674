#pragma once
// Writes a simulated sequence to its folder as it is rendered:
//   sim.rawlog (+ sim_Images/)  CObservation3DRangeScan "RGBD" (depth uint16 mm), CObservationIMU
//                               "IMU", CObservationGPS "GPS" (GGA), in time order; the camera's
//                               and the IMU's sensorPose say where they sit on the body
//   groundtruth.tum             camera (optical frame) pose in the world, per frame
//   objects.txt                 per frame and visible object: id, class, moving, world pose of
//                               its rigid core, amodal 2-D box, visible pixels and fraction
//   labels/NNNNNN.png           16-bit instance labels (0 = static scene)
//   imu_biases.txt              true gyro and accelerometer biases at each IMU sample
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/sim/SimFrame.h>

#include <fstream>
#include <string>

namespace dynslam::rawlog_tools {

class SimulationWriter {
 public:
  SimulationWriter(const std::string& outDir, const sim::Sequence& sequence);

  /// Writes the IMU and GNSS samples up to the frame's time, then the frame.
  void write(const sim::SimFrame& frame);
  /// Writes the samples after the last frame and closes the rawlog.
  void finish();

  const RawlogWriter& rawlog() const { return rawlog_; }

 private:
  void writeSamplesUpTo(double t);
  double stamp(double t) const { return start_time_ + t; }

  const sim::Sequence& sim_;
  std::string dir_;
  double start_time_;
  RawlogWriter rawlog_;
  ColourImageStore images_;
  std::ofstream groundtruth_, objects_, biases_;
  Eigen::Isometry3d T_body_imu_;  // every IMU observation's sensorPose
  size_t next_imu_ = 0, next_gnss_ = 0;
};

}  // namespace dynslam::rawlog_tools
