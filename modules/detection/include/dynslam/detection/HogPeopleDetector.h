#pragma once
// OpenCV's built-in HOG + linear SVM people detector (Dalal-Triggs, 64x128 window), so the system
// finds people with no model file at all. It reports COCO class person only (through the class
// map: if person is mapped to nothing, it reports nothing).
#include <dynslam/detection/ClassMap.h>
#include <dynslam/detection/Detector.h>

#include <opencv2/objdetect.hpp>

namespace dynslam::detection {

/// Keys, ranges, meanings: DetectionOptions::describe() in DetectionOptions.cpp;
/// docs/parameters.md. win_stride must be a multiple of the 8-pixel cell (the constructor
/// checks). Below 128, min_height finds smaller people, slower (the image is resized by
/// 128 / min_height: the window is 128 high); above it, runs faster on large people only.
struct HogPeopleDetectorSettings {
  double scale = 1.05;
  double hit_threshold = 0.0;
  int win_stride = 8;
  int min_height = 128;
  double nms_iou = 0.45;
};

class HogPeopleDetector : public Detector {
 public:
  /// Throws DetectorError for a win_stride that is not a positive multiple of 8.
  HogPeopleDetector(HogPeopleDetectorSettings settings, ClassMap class_map);

  /// Boxes are the windows shrunk to the person inside them (OpenCV's peopledetect sample does
  /// the same); score = logistic(SVM margin). Throws DetectorError for a frame without colour.
  std::vector<core::Detection> detect(const core::Frame& frame) override;

 private:
  HogPeopleDetectorSettings settings_;
  ClassMap class_map_;
  cv::HOGDescriptor hog_;
};

}  // namespace dynslam::detection
