#pragma once
// OpenCV's built-in HOG + linear SVM people detector (Dalal-Triggs, 64x128 window), so the system
// finds people with no model file at all. It reports COCO class person only (through the class
// map: if person is mapped to nothing, it reports nothing).
#include <dynslam/detection/ClassMap.h>
#include <dynslam/detection/Detector.h>

#include <opencv2/objdetect.hpp>

namespace dynslam::detection {

struct HogPeopleDetectorSettings {
  double scale = 1.05;         ///< step between pyramid levels (> 1; larger: faster, coarser)
  double hit_threshold = 0.0;  ///< minimum SVM margin of a window
  int win_stride = 8;          ///< pixels between windows (a multiple of the 8-pixel cell)
  /// Smallest person height to find, pixels: the image is resized by 128 / min_height before
  /// detection (the window is 128 high), so below 128 it finds smaller people, slower, and
  /// above it runs faster on large people only.
  int min_height = 128;
  double nms_iou = 0.45;  ///< overlapping windows with a higher IoU than this are merged (NMS)
};

class HogPeopleDetector : public Detector {
 public:
  /// Throws DetectorError for settings out of range.
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
