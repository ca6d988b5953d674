#include "dynslam/detection/DetectionOptions.h"

#include <dynslam/core/Config.h>

#include <mrpt/config/CConfigFileBase.h>

namespace dynslam::detection {
namespace {

std::string layoutName(YoloLayout layout) {
  switch (layout) {
    case YoloLayout::YoloX:
      return "yolox";
    case YoloLayout::YoloV5:
      return "yolov5";
    case YoloLayout::YoloV8:
      return "yolov8";
  }
  return "";
}

}  // namespace

DetectionOptions::DetectionOptions() : class_map(ClassMap().toString()) {}

void DetectionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                          const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(detector, string, c, s);
  MRPT_LOAD_CONFIG_VAR(mode, string, c, s);
  MRPT_LOAD_CONFIG_VAR(class_map, string, c, s);
  if (detector == "onnx_yolo") {
    auto& o = onnx_yolo;
    o.model = c.read_string(s, "model", o.model);
    // std::invalid_argument for an unknown name; DetectionStage adds the section and source.
    o.layout = parseYoloLayout(c.read_string(s, "layout", layoutName(o.layout)));
    o.input_size = c.read_int(s, "input_size", o.input_size);
    o.trim_padding = core::readBool(c, s, "trim_padding", o.trim_padding);
    o.confidence = c.read_double(s, "confidence", o.confidence);
    o.nms_iou = c.read_double(s, "nms_iou", o.nms_iou);
    o.threads = c.read_int(s, "threads", o.threads);
  } else if (detector == "hog") {
    auto& o = hog;
    o.scale = c.read_double(s, "scale", o.scale);
    o.hit_threshold = c.read_double(s, "hit_threshold", o.hit_threshold);
    o.win_stride = c.read_int(s, "win_stride", o.win_stride);
    o.min_height = c.read_int(s, "min_height", o.min_height);
    o.nms_iou = c.read_double(s, "nms_iou", o.nms_iou);
  } else if (detector == "ground_truth") {
    auto& o = ground_truth;
    o.objects = c.read_string(s, "objects", o.objects);
    o.miss_rate = c.read_double(s, "miss_rate", o.miss_rate);
    o.jitter_px = c.read_double(s, "jitter_px", o.jitter_px);
    o.false_positive_rate = c.read_double(s, "false_positive_rate", o.false_positive_rate);
    o.min_visible_fraction = c.read_double(s, "min_visible_fraction", o.min_visible_fraction);
    const int seed = c.read_int(s, "seed", static_cast<int>(o.seed));
    o.seed = static_cast<std::uint32_t>(seed);
  }
}

void DetectionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                        const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(detector, "onnx_yolo | hog | ground_truth (its keys follow)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(mode,
                               "deterministic: detect every frame inline | realtime: detector "
                               "thread at its own rate, frames it skips get no detections");
  MRPT_SAVE_CONFIG_VAR_COMMENT(class_map,
                               "coco_class:person|car|other:rigid|non_rigid ...; unmapped "
                               "classes are dropped");
  if (detector == "onnx_yolo") {
    const auto& o = onnx_yolo;
    core::writeKey(c, s, "model", o.model, "ONNX file (relative: working directory)");
    core::writeKey(c, s, "layout", layoutName(o.layout),
        "output layout: yolox (BGR 0-255) | yolov5 | yolov8 (RGB 0-1)");
    core::writeKey(c, s, "input_size", o.input_size,
                   "network input, px (multiple of 32), the image's longer side");
    core::writeKey(c, s, "trim_padding", o.trim_padding,
                   "drop the letterbox's grey rows (416x320, not 416x416, for 4:3); false for a "
                   "model with a fixed square input");
    core::writeKey(c, s, "confidence", o.confidence, "minimum score (objectness x class)");
    core::writeKey(c, s, "nms_iou", o.nms_iou, "NMS IoU threshold within a category");
    core::writeKey(c, s, "threads", o.threads, "cv::setNumThreads (process-wide); 0: default");
  } else if (detector == "hog") {
    const auto& o = hog;
    core::writeKey(c, s, "scale", o.scale, "pyramid step (> 1)");
    core::writeKey(c, s, "hit_threshold", o.hit_threshold, "minimum SVM margin");
    core::writeKey(c, s, "win_stride", o.win_stride, "px between windows (multiple of 8)");
    core::writeKey(c, s, "min_height", o.min_height,
        "smallest person, px (image resized by 128 / min_height)");
    core::writeKey(c, s, "nms_iou", o.nms_iou, "NMS IoU threshold");
  } else if (detector == "ground_truth") {
    const auto& o = ground_truth;
    core::writeKey(c, s, "objects", o.objects, "dynslam-sim objects.txt (relative: working dir)");
    core::writeKey(c, s, "miss_rate", o.miss_rate, "probability a visible object is missed");
    core::writeKey(c, s, "jitter_px", o.jitter_px, "Gaussian sigma per box edge, px");
    core::writeKey(c, s, "false_positive_rate", o.false_positive_rate,
        "mean random boxes per frame (Poisson)");
    core::writeKey(c, s, "min_visible_fraction", o.min_visible_fraction,
        "less visible objects are not reported");
    core::writeKey(c, s, "seed", static_cast<int>(o.seed), "noise seed (same seed: same boxes)");
  }
}

}  // namespace dynslam::detection
