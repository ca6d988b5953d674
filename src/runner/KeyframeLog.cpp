#include "KeyframeLog.h"

#include <dynslam/core/Frame.h>

#include <cmath>
#include <iomanip>
#include <stdexcept>

namespace dynslam::runner {

KeyframeLog::KeyframeLog(const std::string& path) : path_(path), out_(path, std::ios::trunc) {
  out_ << "frame,t_s,reason,static_features,shared_features,nonrigid_features,rigid_objects,"
          "solve_ms,iterations,restarted,visual_inertial,vx,vy,vz,acc_bias_x,acc_bias_y,"
          "acc_bias_z,gyro_bias_x,gyro_bias_y,gyro_bias_z,time_offset_ms,"
          "extrinsic_rotation_change_x_deg,extrinsic_rotation_change_y_deg,"
          "extrinsic_rotation_change_z_deg,"
          "extrinsic_translation_change_x,extrinsic_translation_change_y,"
          "extrinsic_translation_change_z,time_offset_free,extrinsic_free\n";
  if (!out_) throw std::runtime_error("cannot write the keyframe log '" + path + "'");
}

void KeyframeLog::append(const core::Frame& frame) {
  if (!frame.keyframe) return;
  const core::KeyframeRecord& k = *frame.keyframe;
  out_ << frame.index << ',' << std::fixed << std::setprecision(6) << frame.t << ',' << k.reason
       << ',' << k.static_features << ',' << k.shared_features << ',' << k.nonrigid_features << ','
       << k.rigid_objects << ',' << std::setprecision(3) << k.solve_ms << ',' << k.iterations << ','
       << int(k.restarted) << ',' << int(k.visual_inertial) << std::setprecision(6);
  for (const auto* v : {&k.velocity, &k.acc_bias, &k.gyro_bias})
    out_ << ',' << (*v)(0) << ',' << (*v)(1) << ',' << (*v)(2);
  const Eigen::Vector3d rotationDeg = k.extrinsic_rotation_change * (180 / M_PI);
  out_ << ',' << 1e3 * k.time_offset;
  for (const auto* v : {&rotationDeg, &k.extrinsic_translation_change})
    out_ << ',' << (*v)(0) << ',' << (*v)(1) << ',' << (*v)(2);
  out_ << ',' << int(k.time_offset_free) << ',' << int(k.extrinsic_free) << '\n';
  // Flushed per row, as timing.csv: a kill -9 leaves every row before it whole.
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write the keyframe log '" + path_ + "'");
}

}  // namespace dynslam::runner
