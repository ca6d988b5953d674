#pragma once
// The pipeline stage of depth-threshold instance segmentation (method.md section 1): one
// core::ObjectMask per core::Detection of the frame, in the same order, into
// Frame::object_masks. Runs after a detector stage; reads Frame::depth and
// Frame::detections. Ini section: [Segmentation] (keys in SegmentationOptions).
#include <dynslam/core/Stage.h>
#include <dynslam/segmentation/DepthThresholdSegmenter.h>

#include <mrpt/config/CLoadableOptions.h>

#include <cstddef>

namespace dynslam::segmentation {

struct SegmentationOptions : mrpt::config::CLoadableOptions {
  DepthThresholdParams params;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
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
};

}  // namespace dynslam::segmentation
