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
//   calibration.txt             the true and the believed camera-IMU calibration ([Calibration])
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/sim/CalibrationErrors.h>
#include <dynslam/sim/SimFrame.h>

#include <fstream>
#include <string>

namespace dynslam::rawlog_tools {

/// Sensor faults written into the rawlog on purpose, to test how the system survives them
/// (issue 6: an IMU gap, black frames, frames without depth). The ground truth is unchanged.
struct SensorFaults {
  double imu_gap_start = -1, imu_gap_duration = 0;  ///< s from the start; IMU samples dropped
  long black_first = -1, black_count = 0;           ///< frames whose colour image is all black
  long no_depth_first = -1, no_depth_count = 0;     ///< frames whose depth is all 0 (invalid)
};

class SimulationWriter {
 public:
  /// `calibration`: the stamps and the believed extrinsic the rawlog gets (CalibrationErrors.h);
  /// the truth goes to calibration.txt.
  SimulationWriter(const std::string& outDir, const sim::Sequence& sequence,
                   SensorFaults faults = {}, sim::CalibrationErrorOptions calibration = {});

  /// Writes the IMU and GNSS samples up to the frame's time, then the frame.
  void write(const sim::SimFrame& frame);
  /// Writes the samples after the last frame and closes the rawlog.
  void finish();

  const RawlogWriter& rawlog() const { return rawlog_; }

 private:
  void writeSamplesUpTo(double t);
  void writeCalibrationTruth() const;
  double stamp(double t) const { return start_time_ + t; }

  const sim::Sequence& sim_;
  std::string dir_;
  double start_time_;
  RawlogWriter rawlog_;
  ColourImageStore images_;
  std::ofstream groundtruth_, objects_, biases_;
  Eigen::Isometry3d T_body_imu_;  // every IMU observation's sensorPose
  size_t next_imu_ = 0, next_gnss_ = 0;
  SensorFaults faults_;
  sim::CalibrationErrorOptions calibration_;
  Eigen::Isometry3d believed_T_body_camera_;  // the RGB-D observations' sensorPose
};

}  // namespace dynslam::rawlog_tools
