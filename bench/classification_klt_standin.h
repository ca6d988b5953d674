#pragma once
// bench-classification's stand-in for the FeatureTracking stage while that stage is not in the
// build (or with --features klt): Shi-Tomasi corners (cv::goodFeaturesToTrack, 150, min spacing
// 20 px) tracked by pyramidal KLT (cv::calcOpticalFlowPyrLK) with a forward-backward check,
// replenished every frame, depth from the depth image at the rounded pixel. Gives
// Frame::features ids, pixels, depths and track lengths, as the stage will.
#include <dynslam/core/Frame.h>

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

namespace dynslam::bench {

class KltStandIn {
 public:
  void process(core::Frame& frame);

 private:
  cv::Mat prevGray_;
  std::vector<core::Feature> prev_;
  std::int64_t nextId_ = 0;
};

}  // namespace dynslam::bench
