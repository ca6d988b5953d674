#pragma once
// The pipeline stage of depth-threshold instance segmentation (method.md section 1). Ini
// section: [Segmentation] (keys: SegmentationOptions::describe()). Three uses, chosen by
// `boxes`:
//  - detections (default): one core::ObjectMask per core::Detection of the frame, in the same
//    order, into Frame::object_masks. Runs after a detector stage, before tracking (the tracker
//    takes each detection's depth d_t from its mask).
//  - predicted_tracks: runs after the tracking stage and adds a mask for every confirmed track
//    that no detection of this frame took, segmenting its predicted box (mask.detection = -1,
//    mask.track = the track's index). On a frame the real-time detector skipped that is every
//    confirmed track (method.md section 2: "predicted boxes also serve frames in which the
//    detector gave no result"); on a frame with detections it covers the objects the detector
//    missed, while their tracks coast. A pipeline therefore lists the class twice:
//      stages = Detection, Segmentation, Tracking, Segmentation:PredictedBoxes
//    with [PredictedBoxes] boxes = predicted_tracks.
//  - tracked_detections (not the method): runs after the tracking stage and segments the
//    frame's detections again, each box's object cluster chosen by the depth of the track that
//    took it (DepthThresholdSegmenter::segment's expectedDepth); the masks keep their tracks.
//    With Tracking.alternative_depth a track may take a detection by the cluster the
//    segmentation did not choose; this makes the mask follow the track.
#include <dynslam/core/Stage.h>
#include <dynslam/segmentation/DepthThresholdSegmenter.h>

#include <dynslam/core/Options.h>

#include <cstddef>

namespace dynslam::segmentation {

/// Which boxes the stage segments (see the file comment).
enum class SegmentedBoxes { Detections, PredictedTracks, TrackedDetections };

/// [Segmentation] (and each other instance's section): every key, its range and meaning in
/// describe() (SegmentationStage.cpp); docs/parameters.md.
struct SegmentationOptions : core::Options {
  DepthThresholdParams params;
  SegmentedBoxes boxes = SegmentedBoxes::Detections;
  int max_track_misses = 0;

  void describe(core::OptionVisitor& v) override;
};

class SegmentationStage : public core::Stage {
 public:
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;

  const SegmentationOptions& options() const { return options_; }

 private:
  SegmentationOptions options_;
  DepthThresholdSegmenter segmenter_;
  size_t frames_ = 0, masks_ = 0, invalid_ = 0;

  void segmentPredictedTracks(core::Frame& frame) const;
  void segmentTrackedDetections(core::Frame& frame) const;
};

}  // namespace dynslam::segmentation
