#include "classification_klt_standin.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace dynslam::bench {
namespace {

constexpr int kMaxFeatures = 150;
constexpr double kMinSpacing = 20;

float depthAt(const cv::Mat& depth, const cv::Point2f& p) {
  const int x = cvRound(p.x), y = cvRound(p.y);
  if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) return 0;
  return depth.at<float>(y, x);
}

}  // namespace

void KltStandIn::process(core::Frame& frame) {
  cv::Mat gray;
  cv::cvtColor(frame.rgb, gray, cv::COLOR_BGR2GRAY);
  std::vector<core::Feature> tracked;
  if (!prevGray_.empty() && !prev_.empty()) {
    std::vector<cv::Point2f> p0, p1, back;
    for (const auto& f : prev_) p0.push_back(f.pixel);
    std::vector<uchar> st, stBack;
    std::vector<float> err;
    cv::calcOpticalFlowPyrLK(prevGray_, gray, p0, p1, st, err, cv::Size(21, 21), 3);
    cv::calcOpticalFlowPyrLK(gray, prevGray_, p1, back, stBack, err, cv::Size(21, 21), 3);
    const cv::Rect image(0, 0, gray.cols, gray.rows);
    for (size_t i = 0; i < p0.size(); ++i) {
      if (!st[i] || !stBack[i] || cv::norm(back[i] - p0[i]) > 0.5) continue;
      if (!image.contains(cv::Point(cvRound(p1[i].x), cvRound(p1[i].y)))) continue;
      core::Feature f = prev_[i];
      f.pixel = p1[i];
      f.depth = depthAt(frame.depth, f.pixel);
      ++f.track_length;
      f.feature_class = core::FeatureClass::Static;
      f.object_id = -1;
      tracked.push_back(f);
    }
  }
  if (int(tracked.size()) < kMaxFeatures) {
    cv::Mat mask(gray.size(), CV_8UC1, cv::Scalar(255));
    for (const auto& f : tracked) cv::circle(mask, f.pixel, int(kMinSpacing), cv::Scalar(0), -1);
    std::vector<cv::Point2f> corners;
    cv::goodFeaturesToTrack(gray, corners, kMaxFeatures - int(tracked.size()), 0.01, kMinSpacing,
                            mask);
    for (const auto& c : corners) {
      core::Feature f;
      f.id = nextId_++;
      f.pixel = c;
      f.depth = depthAt(frame.depth, c);
      tracked.push_back(f);
    }
  }
  frame.features = tracked;
  prev_ = std::move(tracked);
  prevGray_ = gray;
}

}  // namespace dynslam::bench
