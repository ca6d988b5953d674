#pragma once
// Dense RGB-D odometry (OpenCV rgbd: photometric + ICP alignment) tracked against a keyframe,
// which drifts less than chaining frame-to-frame motions. It sees the whole image, moving
// people included: it is the "no dynamic handling" baseline and a pose source for RGB-D only
// runs until the factor-graph estimator exists.
#include <dynslam/core/Stage.h>

#include <dynslam/core/Options.h>

#include <memory>

namespace dynslam::odometry {

/// [RgbdOdometry]: every key, its range and meaning in describe() (RgbdOdometryStage.cpp);
/// docs/parameters.md.
struct RgbdOdometryOptions : core::Options {
  std::string method = "rgbd_icp";
  double min_depth = 0.3;
  double max_depth = 4.0;
  double keyframe_translation = 0.10;
  double keyframe_rotation_deg = 10.0;
  double max_translation = 0.5;
  double max_rotation_deg = 30.0;

  void describe(core::OptionVisitor& v) override;
};

class RgbdOdometryStage : public core::Stage {
 public:
  RgbdOdometryStage();
  ~RgbdOdometryStage() override;

  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  bool estimatesPose() const override { return true; }

  const RgbdOdometryOptions& options() const { return options_; }
  size_t failures() const { return failures_; }
  size_t keyframes() const { return keyframes_; }

 private:
  struct Impl;
  RgbdOdometryOptions options_;
  std::unique_ptr<Impl> impl_;
  size_t failures_ = 0, keyframes_ = 0, frames_ = 0;
};

}  // namespace dynslam::odometry
