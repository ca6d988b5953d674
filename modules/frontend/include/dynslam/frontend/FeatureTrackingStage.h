#pragma once
// The feature tracking stage (method.md section 3; ini section [FeatureTracking]): runs a
// FeatureTracker on each frame and writes frame.features, every feature static with object_id
// -1 (the DynamicClassification stage after it assigns objects and classes). Runs after
// Segmentation so the fundamental-matrix RANSAC sees the object masks; without them every
// feature is a static candidate.
#include <dynslam/core/Options.h>
#include <dynslam/core/SampleReservoir.h>
#include <dynslam/core/Stage.h>
#include <dynslam/frontend/FeatureTracker.h>

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace dynslam::frontend {

/// [FeatureTracking]: every key, its range and meaning in describe() (FeatureTrackingStage.cpp).
struct FeatureTrackingOptions : core::Options {
  FeatureTrackerParams tracker;

  void describe(core::OptionVisitor& v) override;
};

class FeatureTrackingStage : public core::Stage {
 public:
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  /// frames, features_per_frame, corners_detected, gyro_frames, mean_track_length (frames a
  /// track lasted, each track counted once), and the fractions of incoming tracks lost per
  /// frame to KLT, the forward-backward check and the fundamental-matrix RANSAC; per-frame
  /// medians of the tracker's parts (tracking_ms_median: grey image, pyramid, KLT both ways and
  /// RANSAC; extraction_ms_median: spacing and new corners), for paper Table 8's split.
  std::vector<std::pair<std::string, double>> statistics() const override;

  const FeatureTrackingOptions& options() const { return options_; }

 private:
  FeatureTrackingOptions options_;
  std::optional<FeatureTracker> tracker_;
  size_t frames_ = 0, features_ = 0, detected_ = 0, gyroFrames_ = 0;
  size_t incoming_ = 0, lostKlt_ = 0, lostFb_ = 0, lostResidual_ = 0, lostRansac_ = 0,
         lostOcclusion_ = 0;
  std::map<std::int64_t, int> alive_;  // id -> track_length in the last frame
  double endedLengthSum_ = 0;
  size_t ended_ = 0;
  core::SampleReservoir trackingMs_, extractionMs_;  // per frame, FeatureTracker::lastStats
};

}  // namespace dynslam::frontend
