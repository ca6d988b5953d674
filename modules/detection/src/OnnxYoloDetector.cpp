#include "dynslam/detection/OnnxYoloDetector.h"

#include <dynslam/core/Config.h>

#include <opencv2/core/utility.hpp>

#include <fstream>
#include <map>

namespace dynslam::detection {

namespace {

// Maps classes first (dropping the unmapped), then NMS within each category: a "bus" and a
// "car" box on one vehicle mapped to car are one car. Boxes go back to the image's pixels.
std::vector<core::Detection> mappedAndSuppressed(const std::vector<YoloCandidate>& candidates,
                                                 const Letterbox& letterbox, cv::Size image,
                                                 const ClassMap& class_map,
                                                 const OnnxYoloDetectorSettings& s) {
  struct Kept {
    cv::Rect2f box;
    float score;
    MappedClass mapped;
  };
  std::map<std::string, std::vector<Kept>> by_category;
  const cv::Rect2f image_rect(0, 0, float(image.width), float(image.height));
  for (const auto& c : candidates) {
    auto mapped = class_map.lookup(c.class_id);
    if (!mapped) continue;
    const cv::Rect2f box = letterbox.toImage(c.box) & image_rect;
    if (box.width < 1 || box.height < 1) continue;
    by_category[mapped->category].push_back({box, c.score, std::move(*mapped)});
  }
  std::vector<core::Detection> detections;
  for (const auto& [category, kept] : by_category) {
    std::vector<cv::Rect2d> boxes;
    std::vector<float> scores;
    for (const auto& k : kept) boxes.emplace_back(k.box), scores.push_back(k.score);
    std::vector<int> keep;
    cv::dnn::NMSBoxes(boxes, scores, static_cast<float>(s.confidence),
                      static_cast<float>(s.nms_iou), keep);
    for (const int i : keep) {
      const Kept& k = kept[static_cast<std::size_t>(i)];
      core::Detection d;
      d.box = k.box;
      d.category = k.mapped.category;
      d.model = k.mapped.model;
      d.score = k.score;
      detections.push_back(d);
    }
  }
  return detections;
}

}  // namespace

OnnxYoloDetector::OnnxYoloDetector(OnnxYoloDetectorSettings settings, ClassMap class_map)
    : settings_(std::move(settings)), class_map_(std::move(class_map)) {
  const auto& s = settings_;
  if (s.input_size < 32 || s.input_size % 32 != 0)
    throw DetectorError("YOLO input_size = " + std::to_string(s.input_size) +
                        ": must be a positive multiple of 32 (the coarsest stride)");
  // Checked first: OpenCV's own message for a missing file is an assertion deep in its parser.
  if (!std::ifstream(s.model, std::ios::binary))
    throw DetectorError("cannot read the YOLO model '" + s.model + "' (missing or unreadable)" +
                        core::pathLookup(s.model));
  try {
    net_ = cv::dnn::readNetFromONNX(s.model);
  } catch (const cv::Exception& e) {
    throw DetectorError("cannot load the YOLO model '" + s.model + "' as ONNX: " + e.what());
  }
  if (net_.empty()) throw DetectorError("the YOLO model '" + s.model + "' holds no network");
  net_.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  net_.setPreferableTarget(cv::dnn::DNN_TARGET_CPU);
  if (s.threads > 0) cv::setNumThreads(s.threads);
}

std::vector<core::Detection> OnnxYoloDetector::detect(const core::Frame& frame) {
  if (frame.rgb.empty())
    throw DetectorError("YOLO detector: frame " + std::to_string(frame.index) +
                        " has no colour image");
  return detectImage(frame.rgb);
}

std::vector<core::Detection> OnnxYoloDetector::detectImage(const cv::Mat& bgr) {
  const auto& s = settings_;
  Letterbox letterbox;
  const cv::Mat input = letterbox.apply(bgr, s.input_size, s.trim_padding);
  const bool ultralytics = s.layout != YoloLayout::YoloX;
  net_.setInput(cv::dnn::blobFromImage(input, ultralytics ? 1.0 / 255.0 : 1.0, cv::Size(),
                                       cv::Scalar(), /*swapRB=*/ultralytics, /*crop=*/false));
  cv::Mat output;
  try {
    output = net_.forward();
  } catch (const cv::Exception& e) {
    if (!s.trim_padding) throw;
    throw DetectorError("YOLO model '" + s.model + "' does not take a " +
                        std::to_string(input.cols) + "x" + std::to_string(input.rows) +
                        " input (exported with a fixed square input?): set trim_padding = false (" +
                        e.what() + ")");
  }

  std::vector<YoloCandidate> candidates;
  try {
    candidates = decodeYoloOutput(output, s.layout, input.size(), static_cast<float>(s.confidence));
  } catch (const std::invalid_argument& e) {
    throw DetectorError("YOLO model '" + s.model + "': " + e.what() + " (is `layout` right?)");
  }

  return mappedAndSuppressed(candidates, letterbox, bgr.size(), class_map_, s);
}

}  // namespace dynslam::detection
