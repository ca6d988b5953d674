#include <dynslam/sim/VideoForeground.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::sim {

cv::Mat medianBackground(const std::vector<cv::Mat>& samples) {
  if (samples.empty()) throw std::invalid_argument("medianBackground: no frames");
  const cv::Mat& first = samples.front();
  for (const auto& s : samples)
    if (s.size() != first.size() || s.type() != CV_8UC3)
      throw std::invalid_argument("medianBackground: frames must all be BGR of one size");
  cv::Mat out(first.size(), CV_8UC3);
  std::vector<uchar> values(samples.size());
  const size_t mid = values.size() / 2;
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        for (size_t i = 0; i < samples.size(); ++i) values[i] = samples[i].at<cv::Vec3b>(y, x)[c];
        std::nth_element(values.begin(), values.begin() + long(mid), values.end());
        out.at<cv::Vec3b>(y, x)[c] = values[mid];
      }
  return out;
}

namespace {

/// A darker copy of the background's colour: brightness ratio in range, chromaticity close.
bool isShadow(const cv::Vec3b& p, const cv::Vec3b& b, const ForegroundOptions& o) {
  const double sp = double(p[0]) + p[1] + p[2], sb = double(b[0]) + b[1] + b[2];
  if (sb < 30 || sp <= 0) return false;  // too dark to tell a shadow's colour
  const double ratio = sp / sb;
  if (ratio < o.shadow_min_ratio || ratio > o.shadow_max_ratio) return false;
  for (int c = 0; c < 3; ++c)
    if (std::abs(p[c] / sp - b[c] / sb) > o.shadow_chroma) return false;
  return true;
}

}  // namespace

cv::Mat foregroundMask(const cv::Mat& bgr, const cv::Mat& background,
                       const ForegroundOptions& options) {
  if (bgr.size() != background.size() || bgr.type() != CV_8UC3 || background.type() != CV_8UC3)
    throw std::invalid_argument(
        "foregroundMask: the frame and the background differ in size or type");
  cv::Mat mask(bgr.size(), CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x), b = background.at<cv::Vec3b>(y, x);
      int diff = 0;
      for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(p[c]) - int(b[c])));
      if (diff > options.threshold && !isShadow(p, b, options)) mask.at<uchar>(y, x) = 255;
    }
  const auto ellipse = [](int size) {
    return cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size));
  };
  cv::morphologyEx(mask, mask, cv::MORPH_OPEN, ellipse(3));
  cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, ellipse(7));
  return mask;
}

std::vector<ForegroundBlob> foregroundBlobs(const cv::Mat& mask, int min_height) {
  cv::Mat grown, labels, stats, centroids;
  const int reach = std::max(1, min_height / 10);
  cv::dilate(mask, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 2 * reach + 1)));
  const int n = cv::connectedComponentsWithStats(grown, labels, stats, centroids, 8, CV_32S);
  std::vector<ForegroundBlob> blobs;
  for (int label = 1; label < n; ++label) {
    const cv::Rect grownBox(
        stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
        stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
    if (grownBox.height < min_height) continue;
    cv::Mat own = (labels(grownBox) == label) & mask(grownBox);
    const cv::Rect tight = cv::boundingRect(own);
    if (tight.height < min_height) continue;
    ForegroundBlob blob{tight + grownBox.tl(), own(tight).clone(), cv::countNonZero(own)};
    blobs.push_back(std::move(blob));
  }
  std::sort(blobs.begin(), blobs.end(), [](const ForegroundBlob& a, const ForegroundBlob& b) {
    return std::make_pair(a.box.y, a.box.x) < std::make_pair(b.box.y, b.box.x);
  });
  return blobs;
}

}  // namespace dynslam::sim
