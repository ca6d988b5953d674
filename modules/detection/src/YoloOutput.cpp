#include "dynslam/detection/YoloOutput.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace dynslam::detection {
namespace {

std::string shapeOf(const cv::Mat& m) {
  std::string s;
  for (int i = 0; i < m.dims; ++i) s += (i ? "x" : "") + std::to_string(m.size[i]);
  return s;
}

/// Index and value of the largest of n scores spaced `step` floats apart.
std::pair<int, float> bestClass(const float* scores, int n, int step) {
  int best = 0;
  for (int c = 1; c < n; ++c)
    if (scores[c * step] > scores[best * step]) best = c;
  return {best, scores[best * step]};
}

cv::Rect2f fromCentre(float cx, float cy, float w, float h) {
  return {cx - 0.5f * w, cy - 0.5f * h, w, h};
}

void decodeYoloX(const cv::Mat& out, cv::Size input, float min_score,
                 std::vector<YoloCandidate>& result) {
  const int rows = out.size[1], width = out.size[2], classes = width - 5;
  int expected = 0;
  for (const int stride : {8, 16, 32}) expected += (input.width / stride) * (input.height / stride);
  if (rows != expected || classes < 1)
    throw std::invalid_argument("YOLOX output " + shapeOf(out) + " does not fit an input of " +
                                std::to_string(input.width) + "x" + std::to_string(input.height) +
                                " (expected 1x" + std::to_string(expected) + "x(5 + classes))");
  const float* p = out.ptr<float>();
  for (const int stride : {8, 16, 32}) {
    const int cols = input.width / stride, gridRows = input.height / stride;
    for (int gy = 0; gy < gridRows; ++gy)
      for (int gx = 0; gx < cols; ++gx, p += width) {
        const float objectness = p[4];
        if (objectness < min_score) continue;  // the product cannot reach min_score
        const auto [cls, cls_score] = bestClass(p + 5, classes, 1);
        const float score = objectness * cls_score;
        if (score < min_score) continue;
        const float s = static_cast<float>(stride);
        result.push_back(
            {fromCentre((p[0] + gx) * s, (p[1] + gy) * s, std::exp(p[2]) * s, std::exp(p[3]) * s),
             cls, score});
      }
  }
}

void decodeYoloV5(const cv::Mat& out, float min_score, std::vector<YoloCandidate>& result) {
  const int rows = out.size[1], width = out.size[2], classes = width - 5;
  if (classes < 1)
    throw std::invalid_argument("YOLOv5 output " + shapeOf(out) + ": expected 1xNx(5 + classes)");
  for (int r = 0; r < rows; ++r) {
    const float* p = out.ptr<float>() + static_cast<std::size_t>(r) * width;
    if (p[4] < min_score) continue;
    const auto [cls, cls_score] = bestClass(p + 5, classes, 1);
    const float score = p[4] * cls_score;
    if (score >= min_score) result.push_back({fromCentre(p[0], p[1], p[2], p[3]), cls, score});
  }
}

void decodeYoloV8(const cv::Mat& out, float min_score, std::vector<YoloCandidate>& result) {
  const int channels = out.size[1], n = out.size[2], classes = channels - 4;
  if (classes < 1)
    throw std::invalid_argument("YOLOv8 output " + shapeOf(out) + ": expected 1x(4 + classes)xN");
  const float* base = out.ptr<float>();
  for (int i = 0; i < n; ++i) {
    const float* p = base + i;  // channel c of proposal i is at p[c * n]
    const auto [cls, score] = bestClass(p + 4 * static_cast<std::size_t>(n), classes, n);
    if (score >= min_score)
      result.push_back({fromCentre(p[0], p[n], p[2 * n], p[3 * n]), cls, score});
  }
}

}  // namespace

cv::Mat Letterbox::apply(const cv::Mat& bgr, int input_size, bool trim) {
  scale = std::min(double(input_size) / bgr.cols, double(input_size) / bgr.rows);
  const cv::Size resized(std::max(1, int(std::lround(bgr.cols * scale))),
                         std::max(1, int(std::lround(bgr.rows * scale))));
  const auto side = [&](int pixels) { return trim ? (pixels + 31) / 32 * 32 : input_size; };
  cv::Mat input(side(resized.height), side(resized.width), CV_8UC3, cv::Scalar::all(114));
  cv::Mat top_left = input(cv::Rect(cv::Point(0, 0), resized));  // resize writes into it
  cv::resize(bgr, top_left, resized, 0, 0, cv::INTER_LINEAR);
  return input;
}

cv::Rect2f Letterbox::toImage(const cv::Rect2f& b) const {
  const float k = static_cast<float>(1.0 / scale);
  return {b.x * k, b.y * k, b.width * k, b.height * k};
}

std::vector<YoloCandidate> decodeYoloOutput(const cv::Mat& output, YoloLayout layout,
                                            cv::Size input, float min_score) {
  if (output.dims != 3 || output.size[0] != 1 || output.type() != CV_32F || !output.isContinuous())
    throw std::invalid_argument("YOLO output " + shapeOf(output) +
                                ": expected a continuous 3-dimensional float blob of batch 1");
  std::vector<YoloCandidate> result;
  switch (layout) {
    case YoloLayout::YoloX:
      decodeYoloX(output, input, min_score, result);
      break;
    case YoloLayout::YoloV5:
      decodeYoloV5(output, min_score, result);
      break;
    case YoloLayout::YoloV8:
      decodeYoloV8(output, min_score, result);
      break;
  }
  return result;
}

}  // namespace dynslam::detection
