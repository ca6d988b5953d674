#include "dynslam/tracking/Appearance.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace dynslam::tracking {

cv::Mat torsoHistogram(const cv::Mat& bgr, const cv::Rect2f& box) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return {};
  const cv::Rect torso =
      cv::Rect(cvRound(box.x + 0.25f * box.width), cvRound(box.y + 0.2f * box.height),
               cvRound(0.5f * box.width), cvRound(0.4f * box.height)) &
      cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (torso.area() < 50) return {};
  cv::Mat hsv;
  cv::cvtColor(bgr(torso), hsv, cv::COLOR_BGR2HSV);  // H in [0, 180)
  cv::Mat hist = cv::Mat::zeros(1, kAppearanceBins, CV_32F);
  float* h = hist.ptr<float>();
  for (int y = 0; y < hsv.rows; ++y) {
    const cv::Vec3b* row = hsv.ptr<cv::Vec3b>(y);
    for (int x = 0; x < hsv.cols; ++x) {
      const int hue = row[x][0], sat = row[x][1], val = row[x][2];
      if (val < 40 || sat < 40)
        ++h[64 + std::min(3, val / 64)];
      else
        ++h[std::min(15, hue * 16 / 180) * 4 + std::min(3, sat / 64)];
    }
  }
  hist /= double(torso.area());
  return hist;
}

cv::Mat observationAppearance(const core::Frame& frame, size_t detection) {
  if (detection >= frame.detections.size()) return {};
  return torsoHistogram(frame.rgb, frame.detections[detection].box);
}

double appearanceDistance(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty() || b.empty() || a.size() != b.size()) return 1.0;
  double bc = 0;  // Bhattacharyya coefficient of two L1-normalised histograms
  const float *pa = a.ptr<float>(), *pb = b.ptr<float>();
  for (int i = 0; i < a.cols; ++i) bc += std::sqrt(double(pa[i]) * pb[i]);
  return std::sqrt(std::max(0.0, 1.0 - bc));
}

}  // namespace dynslam::tracking
