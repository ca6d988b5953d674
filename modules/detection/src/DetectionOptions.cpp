#include "dynslam/detection/DetectionOptions.h"

namespace dynslam::detection {
namespace {

using core::Range;

constexpr core::Keyword<YoloLayout> kLayouts[] = {
    {"yolox", YoloLayout::YoloX}, {"yolov5", YoloLayout::YoloV5}, {"yolov8", YoloLayout::YoloV8}};

void describeOnnxYolo(core::OptionVisitor& v, OnnxYoloDetectorSettings& o) {
  v.path("model", o.model,
         "ONNX file (relative: from the working directory, else the ini's folder)");
  v.key("layout", o.layout, kLayouts,
        "output layout: yolox (BGR 0-255) | yolov5 | yolov8 (RGB 0-1)");
  v.key("input_size", o.input_size, Range::atLeast(32),
        "network input, px (multiple of 32), the image's longer side");
  v.key("trim_padding", o.trim_padding,
        "drop the letterbox's grey rows (416x320, not 416x416, for 4:3); false for a model with a "
        "fixed square input");
  v.key("confidence", o.confidence, Range{0, 1, true, true}, "minimum score (objectness x class)");
  v.key("nms_iou", o.nms_iou, Range{0, 1, true, false}, "NMS IoU threshold within a category");
  v.key("threads", o.threads, Range::atLeast(0), "cv::setNumThreads (process-wide); 0: default");
}

void describeHog(core::OptionVisitor& v, HogPeopleDetectorSettings& o) {
  v.key("scale", o.scale, Range::above(1), "pyramid step");
  v.key("hit_threshold", o.hit_threshold, Range::any(), "minimum SVM margin");
  v.key("win_stride", o.win_stride, Range::atLeast(8), "px between windows (multiple of 8)");
  v.key("min_height", o.min_height, Range::atLeast(16),
        "smallest person, px (image resized by 128 / min_height)");
  v.key("nms_iou", o.nms_iou, Range::closed(0, 1), "NMS IoU threshold");
}

void describeGroundTruth(core::OptionVisitor& v, GroundTruthDetectorSettings& o) {
  v.path("objects", o.objects,
         "dynslam-sim objects.txt (relative: from the working directory, else the ini's folder); "
         "feed:NAME reads what a program adds while the run goes on (dynslam-nav-demo)");
  v.key("miss_rate", o.miss_rate, Range::closed(0, 1), "probability a visible object is missed");
  v.key("jitter_px", o.jitter_px, Range::atLeast(0), "Gaussian sigma per box edge, px");
  v.key("false_positive_rate", o.false_positive_rate, Range::atLeast(0),
        "mean random boxes per frame (Poisson)");
  v.key("min_visible_fraction", o.min_visible_fraction, Range::closed(0, 1),
        "less visible objects are not reported");
  v.key("seed", o.seed, Range::atLeast(0), "noise seed (same seed: same boxes)");
}

}  // namespace

const std::vector<std::string> DetectionOptions::kDetectors = {"onnx_yolo", "hog", "ground_truth"};

DetectionOptions::DetectionOptions() : class_map(ClassMap().toString()) {}

void DetectionOptions::describe(core::OptionVisitor& v) {
  // The parameter reference lists each detector's keys apart by the "(its keys follow)" mark.
  v.word("detector", detector, kDetectors, "onnx_yolo | hog | ground_truth (its keys follow)");
  v.word("mode", mode, {"deterministic", "realtime"},
         "deterministic: detect every frame inline | realtime: detector thread at its own rate, "
         "frames it skips get no detections");
  v.key("class_map", class_map,
        "coco_class:person|car|other:rigid|non_rigid ...; unmapped classes are dropped");
  if (detector == "onnx_yolo")
    describeOnnxYolo(v, onnx_yolo);
  else if (detector == "hog")
    describeHog(v, hog);
  else if (detector == "ground_truth")
    describeGroundTruth(v, ground_truth);
}

}  // namespace dynslam::detection
