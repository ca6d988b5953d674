#pragma once
// A static camera's video of textured figures walking across a textured background, with each
// figure's true mask per frame: ground truth for cutting people out of video (sim::SpriteExtractor,
// dynslam-sprites).
#include <opencv2/core/mat.hpp>

#include <vector>

namespace dynslam::testing {

/// A figure walking in a straight line at constant speed over the scene's frames.
struct SyntheticWalker {
  cv::Point2f foot_start, foot_end;  ///< where it stands in the first and the last frame
  int height_px = 150;               ///< head to foot
  cv::Scalar colour_a{40, 40, 200}, colour_b{200, 60, 40};  ///< its clothes' stripes (BGR)
};

struct SyntheticWalkerScene {
  cv::Size size{640, 360};
  int frames = 48;
  std::vector<SyntheticWalker> walkers;

  /// Frame i (BGR) with two grey levels of sensor noise; `masks` (when given) receives each
  /// walker's visible pixels (CV_8UC1, 255), nearer walkers (larger foot y) hiding farther ones.
  cv::Mat frame(int i, std::vector<cv::Mat>* masks = nullptr) const;
  /// The textured grey background alone, without noise.
  cv::Mat background() const;
};

}  // namespace dynslam::testing
