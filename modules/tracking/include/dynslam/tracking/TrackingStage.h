#pragma once
// The tracking stage (method.md section 2; ini section [Tracking]): runs a KalmanBoxTracker on
// the frame's detections and writes frame.tracks. The depth of each detection is the
// segmentation's d_t when an earlier stage wrote object_masks, else the median depth of the
// box's central half (ObjectDepth.h). Each mask's ObjectMask::track is set to the index of the
// track its detection was matched to (-1: none), so later stages know which object a mask is.
//
// Real-time mode: on a frame whose detections are not fresh (frame.detections_fresh == false:
// the detector thread was busy) the tracks only predict to the frame's time, and frame.tracks
// carries the predicted boxes (detection = -1) for later stages to use in place of detections.
// Such frames do not count as misses: max_age counts detector frames.
#include <dynslam/core/Stage.h>
#include <dynslam/tracking/KalmanBoxTracker.h>

#include <dynslam/core/Options.h>

namespace dynslam::tracking {

/// [Tracking]: every key, its range and meaning in describe() (TrackingStage.cpp).
struct TrackingOptions : core::Options {
  KalmanBoxTrackerParams tracker;

  void describe(core::OptionVisitor& v) override;
};

class TrackingStage : public core::Stage {
 public:
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;

  const TrackingOptions& options() const { return options_; }

 private:
  TrackingOptions options_;
  KalmanBoxTracker tracker_;
  size_t frames_ = 0, detectorFrames_ = 0;
};

}  // namespace dynslam::tracking
