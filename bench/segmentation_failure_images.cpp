#include "segmentation_failure_images.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace {

cv::Mat overlay(const cv::Mat& rgb, const cv::Mat& mask, const cv::Mat& truth) {
  cv::Mat out = rgb.clone();
  for (int v = 0; v < out.rows; ++v)
    for (int u = 0; u < out.cols; ++u) {
      const bool m = mask.at<uint8_t>(v, u), t = truth.at<uint8_t>(v, u);
      if (!m && !t) continue;
      const cv::Vec3b tint = m && t ? cv::Vec3b(0, 200, 0)
                             : m    ? cv::Vec3b(0, 0, 255)
                                    : cv::Vec3b(255, 0, 0);
      out.at<cv::Vec3b>(v, u) = out.at<cv::Vec3b>(v, u) / 2 + tint / 2;
    }
  return out;
}

}  // namespace

void FailureDumper::consider(const dynslam::sim::SimFrame& f, const dynslam::sim::ObjectTruth& o,
                             const dynslam::core::ObjectMask& m, double iou, double err) {
  if (dir_.empty()) return;
  const double badness = std::max(iou >= 0 ? 1 - iou : 0.0, err / 10);
  if (kept_.size() >= max_ && badness <= kept_.back().badness) return;

  const cv::Rect image({}, f.image.rgb.size());
  const cv::Rect crop = (m.roi + cv::Size(20, 20) - cv::Point(10, 10)) & image;
  cv::Mat mask(f.image.rgb.size(), CV_8UC1, cv::Scalar(0));
  if (m.valid) m.mask.copyTo(mask(m.roi));
  const cv::Mat truth = f.image.label == o.id;
  cv::Mat left = overlay(f.image.rgb(crop), mask(crop), truth(crop));
  cv::rectangle(left, m.roi - crop.tl(), {0, 255, 255});
  cv::Mat depth8, right;
  f.image.depth(crop).convertTo(depth8, CV_8UC1, 255.0 / 6.0);
  cv::applyColorMap(depth8, right, cv::COLORMAP_JET);
  right.setTo(cv::Scalar(0, 0, 0), f.image.depth(crop) == 0);
  std::vector<std::vector<cv::Point>> outline;
  cv::findContours(truth(crop).clone(), outline, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  cv::drawContours(right, outline, -1, {255, 255, 255});
  cv::Mat both;
  cv::hconcat(left, right, both);
  const double scale = std::max(1.0, 300.0 / both.rows);
  cv::resize(both, both, {}, scale, scale, cv::INTER_NEAREST);
  cv::Mat canvas(both.rows + 40, std::max(both.cols, 560), CV_8UC3, cv::Scalar(0, 0, 0));
  both.copyTo(canvas(cv::Rect(0, 0, both.cols, both.rows)));
  char text[200];
  std::snprintf(text, sizeof text, "f%zu id%d vis %.2f IoU %.2f d_t %.2f (err %.1f%%)", f.index,
                o.id, o.visible_fraction, iou, m.d_t, err);
  cv::putText(canvas, text, {4, both.rows + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {255, 255, 255});
  std::snprintf(text, sizeof text, "d_o %.2f d_b %.2f T [%.2f, %.2f]", m.d_o, m.d_b, m.t_min,
                m.t_max);
  cv::putText(canvas, text, {4, both.rows + 34}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {255, 255, 255});

  char name[64];
  std::snprintf(name, sizeof name, "_f%04zu_id%d_iou%.2f_err%.0f.png", f.index, o.id, iou, err);
  kept_.push_back({badness, prefix_ + name, canvas});
  std::sort(kept_.begin(), kept_.end(),
            [](const Kept& a, const Kept& b) { return a.badness > b.badness; });
  if (kept_.size() > max_) kept_.pop_back();
}

void FailureDumper::write() const {
  if (dir_.empty()) return;
  std::filesystem::create_directories(dir_);
  for (const auto& k : kept_) {
    cv::imwrite(dir_ + "/" + k.name, k.image);
    std::printf("wrote %s/%s (badness %.2f)\n", dir_.c_str(), k.name.c_str(), k.badness);
  }
}
