#include "dynslam/tracking/Appearance.h"
#include "dynslam/tracking/ObjectDepth.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynslam::tracking {
namespace {

/// Every kStride-th pixel of every kStride-th row counts: a person's box holds tens of thousands
/// of pixels, far more than 68 bins need, and the tracker runs every frame (time and IDF1 at
/// this stride: docs/notes/perception.md, 2026-11-28, appearance).
constexpr int kStride = 3;

/// Adds the hue-saturation histogram of the pixels of `region` in `bgr` whose depth is within
/// the band of `objectDepth` (all of them when `depth` is empty) to `h` (kPartBins values),
/// normalised to sum to 1; false, leaving `h` zero, when fewer than 50 pixels count (sampled
/// pixels stand for kStride x kStride each).
bool addPartHistogram(const cv::Mat& bgr, cv::Rect region, const cv::Mat& depth, double objectDepth,
                      float* h) {
  region &= cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (region.area() < 50) return false;
  // The sampled pixels within the depth band, gathered into one row before the colour
  // conversion: a box holds a third to a half of background, which need not be converted.
  thread_local std::vector<cv::Vec3b> gathered;
  gathered.clear();
  for (int y = region.y; y < region.y + region.height; y += kStride) {
    const cv::Vec3b* colour = bgr.ptr<cv::Vec3b>(y);
    const float* z = depth.empty() ? nullptr : depth.ptr<float>(y);
    for (int x = region.x; x < region.x + region.width; x += kStride)
      if (!z || std::abs(z[x] - objectDepth) < kAppearanceDepthBand) gathered.push_back(colour[x]);
  }
  const int counted = int(gathered.size());
  if (counted * kStride * kStride < 50) return false;
  cv::Mat hsv;
  cv::cvtColor(cv::Mat(1, counted, CV_8UC3, gathered.data()), hsv, cv::COLOR_BGR2HSV);
  const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(0);  // H in [0, 180)
  for (int i = 0; i < counted; ++i) {
    const int hue = row[i][0], sat = row[i][1], val = row[i][2];
    if (val < 40 || sat < 40)
      ++h[64 + std::min(3, val / 64)];
    else
      ++h[std::min(15, hue * 16 / 180) * 4 + std::min(3, sat / 64)];
  }
  for (int i = 0; i < kPartBins; ++i) h[i] /= float(counted);
  return true;
}

}  // namespace

cv::Mat bodyHistogram(const cv::Mat& bgr, const cv::Rect2f& box, const cv::Mat& depth,
                      double objectDepth) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return {};
  const bool gated =
      objectDepth > 0 && !depth.empty() && depth.type() == CV_32FC1 && depth.size() == bgr.size();
  const cv::Mat& z = gated ? depth : cv::Mat();
  cv::Mat hist = cv::Mat::zeros(1, kAppearanceBins, CV_32F);
  float* h = hist.ptr<float>();
  auto part = [&](float x0, float y0, float x1, float y1) {
    return cv::Rect(cvRound(box.x + x0 * box.width), cvRound(box.y + y0 * box.height),
                    cvRound((x1 - x0) * box.width), cvRound((y1 - y0) * box.height));
  };
  const bool upper = addPartHistogram(bgr, part(0.15f, 0.15f, 0.85f, 0.55f), z, objectDepth, h);
  const bool lower =
      addPartHistogram(bgr, part(0.15f, 0.55f, 0.85f, 0.95f), z, objectDepth, h + kPartBins);
  if (!upper && !lower) return {};
  // A part too hidden to count stands in for the other, so that two descriptors compare
  // part by part either way.
  if (!upper) std::copy(h + kPartBins, h + 2 * kPartBins, h);
  if (!lower) std::copy(h, h + kPartBins, h + kPartBins);
  hist *= 0.5;
  return hist;
}

BoxObservation observeDetection(const core::Frame& frame, size_t detection, bool withAppearance) {
  const core::Detection& d = frame.detections.at(detection);
  BoxObservation o;
  o.box = d.box;
  o.depth = measuredObjectDepth(frame, detection);
  o.depth_alt = alternativeObjectDepth(frame, detection);
  o.category = d.category;
  o.model = d.model;
  if (withAppearance) o.appearance = bodyHistogram(frame.rgb, d.box, frame.depth, o.depth);
  return o;
}

double appearanceDistance(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty() || b.empty() || a.size() != b.size()) return 1.0;
  double bc = 0;  // Bhattacharyya coefficient of two L1-normalised histograms
  const float *pa = a.ptr<float>(), *pb = b.ptr<float>();
  for (int i = 0; i < a.cols; ++i) bc += std::sqrt(double(pa[i]) * pb[i]);
  return std::sqrt(std::max(0.0, 1.0 - bc));
}

}  // namespace dynslam::tracking
