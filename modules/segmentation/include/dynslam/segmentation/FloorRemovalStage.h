#pragma once
// Takes the floor out of every object mask (not the method; ini section [FloorRemoval], keys:
// FloorRemovalOptions::describe()). Fits the floor plane to the depth outside the masks' boxes
// (FloorPlane.h) and clears each mask pixel less than `margin_m` above it. The shipped pipelines
// list it after FeatureTracking, whose fundamental-matrix RANSAC and residual gate work from the
// segmentation's masks as they were, and before DynamicClassification:
//   stages = Detection Segmentation Tracking ... Segmentation:PredictedBoxes FeatureTracking
//            FloorRemoval DynamicClassification
// (Why after FeatureTracking, and what the stage gains: docs/notes/perception.md, "The
// `FloorRemoval` entry".) The masks' depths (d_t, d_o, d_b) stay as the segmentation measured
// them: only which pixels belong to the object changes. A frame without a floor in view keeps
// its masks.
#include <dynslam/core/Stage.h>
#include <dynslam/segmentation/FloorPlane.h>

#include <dynslam/core/Options.h>

#include <cstddef>

namespace dynslam::segmentation {

/// [FloorRemoval]: every key, its range and meaning in describe() (FloorRemovalStage.cpp);
/// docs/parameters.md.
struct FloorRemovalOptions : core::Options {
  FloorPlaneParams plane;
  double margin_m = 0.03;

  void describe(core::OptionVisitor& v) override;
};

/// Clears the pixels of `mask` (over `roi` of `depth`) within the margin of `floor`; returns
/// how many it cleared.
size_t removeFloorPixels(const cv::Mat& depth, const core::CameraIntrinsics& K,
                         const FloorPlane& floor, const FloorRemovalOptions& options,
                         core::ObjectMask& mask);

class FloorRemovalStage : public core::Stage {
 public:
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  /// frames, floor_frames (a floor was found), removed_pixel_fraction (of the masks' pixels).
  std::vector<std::pair<std::string, double>> statistics() const override;

  const FloorRemovalOptions& options() const { return options_; }

 private:
  FloorRemovalOptions options_;
  size_t frames_ = 0, floorFrames_ = 0, maskPixels_ = 0, removedPixels_ = 0;
};

}  // namespace dynslam::segmentation
