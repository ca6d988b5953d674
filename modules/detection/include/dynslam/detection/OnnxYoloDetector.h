#pragma once
// A YOLO-family detector (YOLOX, YOLOv5 or YOLOv8 output layout) run by OpenCV DNN on the CPU:
// letterbox, forward, decode (YoloOutput.h), class map, per-category NMS. Input conventions
// follow the layout: yolox takes BGR 0-255 (as Megvii exports it), yolov5 / yolov8 take RGB
// scaled to 0-1 (as Ultralytics exports them); all are letterboxed top-left with grey 114.
#include <dynslam/detection/ClassMap.h>
#include <dynslam/detection/Detector.h>
#include <dynslam/detection/YoloOutput.h>

#include <opencv2/dnn.hpp>

#include <string>

namespace dynslam::detection {

/// Keys, ranges, meanings: DetectionOptions::describe() in DetectionOptions.cpp;
/// docs/parameters.md. input_size must be a multiple of 32, the coarsest stride (the
/// constructor checks); threads is process-wide (cv::setNumThreads). trim_padding runs 416 x
/// 320 rather than 416 x 416 for a 4:3 image (Letterbox::apply): the same detections for three
/// quarters of the work; a model exported with a fixed square input shape cannot take it.
struct OnnxYoloDetectorSettings {
  std::string model = "../shared/models/yolox_nano.onnx";
  YoloLayout layout = YoloLayout::YoloX;
  int input_size = 416;
  double confidence = 0.35;
  double nms_iou = 0.45;
  int threads = 0;
  bool trim_padding = true;
};

class OnnxYoloDetector : public Detector {
 public:
  /// Loads the model; throws DetectorError naming the path when it is missing or unreadable,
  /// or when input_size is not a positive multiple of 32.
  OnnxYoloDetector(OnnxYoloDetectorSettings settings, ClassMap class_map);

  /// Throws DetectorError for a frame without colour, or when the network's output does not fit
  /// the layout (naming the model, the layout and the shape).
  std::vector<core::Detection> detect(const core::Frame& frame) override;

  /// The detections of one BGR image (what detect() runs on the frame's colour image).
  std::vector<core::Detection> detectImage(const cv::Mat& bgr);

 private:
  OnnxYoloDetectorSettings settings_;
  ClassMap class_map_;
  cv::dnn::Net net_;
};

}  // namespace dynslam::detection
