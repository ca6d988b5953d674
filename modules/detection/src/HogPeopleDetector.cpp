#include "dynslam/detection/HogPeopleDetector.h"

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace dynslam::detection {

HogPeopleDetector::HogPeopleDetector(HogPeopleDetectorSettings settings, ClassMap class_map)
    : settings_(settings), class_map_(std::move(class_map)) {
  if (settings_.win_stride <= 0 || settings_.win_stride % 8 != 0)
    throw DetectorError("HOG win_stride = " + std::to_string(settings_.win_stride) +
                        ": must be a positive multiple of 8 (the cell size)");
  hog_.setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
}

std::vector<core::Detection> HogPeopleDetector::detect(const core::Frame& frame) {
  if (frame.rgb.empty())
    throw DetectorError("HOG people detector: frame " + std::to_string(frame.index) +
                        " has no colour image");
  const auto person = class_map_.lookup(0);
  if (!person) return {};

  const double resize = 128.0 / settings_.min_height;
  cv::Mat image = frame.rgb;
  if (std::abs(resize - 1.0) > 1e-9) cv::resize(frame.rgb, image, cv::Size(), resize, resize);
  std::vector<cv::Rect> windows;
  std::vector<double> margins;
  const cv::Size stride(settings_.win_stride, settings_.win_stride);
  // Group threshold 0: OpenCV's own grouping off, NMS below keeps the best window instead.
  hog_.detectMultiScale(image, windows, margins, settings_.hit_threshold, stride, cv::Size(),
                        settings_.scale, 0.0, false);

  std::vector<cv::Rect2d> boxes;
  std::vector<float> scores;
  for (std::size_t i = 0; i < windows.size(); ++i) {
    const cv::Rect& w = windows[i];
    // The person fills about 80 % of the window's width and height (peopledetect.cpp).
    boxes.emplace_back((w.x + 0.1 * w.width) / resize, (w.y + 0.07 * w.height) / resize,
                       0.8 * w.width / resize, 0.8 * w.height / resize);
    scores.push_back(static_cast<float>(1.0 / (1.0 + std::exp(-margins[i]))));
  }
  std::vector<int> keep;
  cv::dnn::NMSBoxes(boxes, scores, 0.f, static_cast<float>(settings_.nms_iou), keep);

  const cv::Rect2d image_rect(0, 0, frame.rgb.cols, frame.rgb.rows);
  std::vector<core::Detection> detections;
  for (const int i : keep) {
    const cv::Rect2d clipped = boxes[static_cast<std::size_t>(i)] & image_rect;
    if (clipped.width < 1 || clipped.height < 1) continue;
    core::Detection d;
    d.box = cv::Rect2f(clipped);
    d.category = person->category;
    d.model = person->model;
    d.score = scores[static_cast<std::size_t>(i)];
    detections.push_back(d);
  }
  return detections;
}

}  // namespace dynslam::detection
