#pragma once
// What moves in front of a static camera: the median background of sampled frames, each
// frame's foreground against it with cast shadows left out, and the foreground's blobs (one per
// person when people walk apart). The first step of cutting real people out of real video
// (SpriteExtractor.h).
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <vector>

namespace dynslam::sim {

/// Per pixel and channel the median of `samples` (BGR, CV_8UC3, one size): the static scene
/// when each pixel shows it in more than half of them. Throws std::invalid_argument when
/// `samples` is empty or mixes sizes or types.
cv::Mat medianBackground(const std::vector<cv::Mat>& samples);

struct ForegroundOptions {
  /// A pixel is foreground when a channel differs from the background by more than this
  /// (grey levels); video noise is a few levels, a person's clothes against a floor tens.
  double threshold = 30;
  /// A cast shadow darkens the background, keeping its colour: a pixel whose brightness is this
  /// share of the background's ([min, max]) and whose chromaticity (each channel over their
  /// sum) is within `shadow_chroma` of it is shadow, not foreground (Cucchiara et al. 2003).
  double shadow_min_ratio = 0.4, shadow_max_ratio = 0.92, shadow_chroma = 0.05;
};

/// CV_8UC1, 255 where `bgr` shows something the background does not (shadows excluded), after a
/// morphological opening (speckle) and closing (holes in clothes the background's colour).
cv::Mat foregroundMask(const cv::Mat& bgr, const cv::Mat& background,
                       const ForegroundOptions& options = {});

/// One blob of foreground: its box and its pixels (CV_8UC1 of the box's size, 255 on it).
struct ForegroundBlob {
  cv::Rect box;
  cv::Mat mask;
  int area = 0;
};

/// The foreground's blobs at least `min_height` pixels tall. Parts of one person a thin gap
/// splits (the head above a collar the colour of the wall, a leg) are joined: the blobs are the
/// connected parts of the mask grown vertically by a tenth of `min_height`, each holding only the
/// mask's own pixels. Ordered by box (top, then left), so the order never depends on labels.
std::vector<ForegroundBlob> foregroundBlobs(const cv::Mat& mask, int min_height);

}  // namespace dynslam::sim
