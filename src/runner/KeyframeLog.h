#pragma once
// keyframes.csv: one row per keyframe the estimator made (core::KeyframeRecord), for tracing a
// run's drift to where the window saw little or the IMU states moved, and the per-keyframe
// solve time (summary.json keeps its median and maximum).
//   frame,t_s,reason,static_features,shared_features,nonrigid_features,rigid_objects,solve_ms,
//   iterations,restarted,visual_inertial,vx,vy,vz,acc_bias_x,acc_bias_y,acc_bias_z,
//   gyro_bias_x,gyro_bias_y,gyro_bias_z
#include <dynslam/system/FrameSink.h>

#include <fstream>
#include <string>

namespace dynslam::core {
struct Frame;
}

namespace dynslam::runner {

class KeyframeLog : public system::FrameSink {
 public:
  /// Creates (truncates) `path` with the header. Throws std::runtime_error naming the file when
  /// it cannot be written.
  explicit KeyframeLog(const std::string& path);

  /// One row when the frame is a keyframe, nothing otherwise.
  void append(const core::Frame& frame);
  void onFrame(const core::Frame& frame, const system::FrameContext&) override { append(frame); }

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace dynslam::runner
