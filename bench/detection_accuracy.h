#pragma once
// Detection accuracy against a simulated sequence's objects.txt: a frame's person detections
// matched one to one with its true people (box IoU >= 0.5, largest first). People at least
// `min_visible` visible must be found (a miss counts against recall); a detection on a less
// visible person is neither right nor wrong; any other detection is a false positive.
#include <dynslam/core/Frame.h>
#include <dynslam/detection/Detector.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dynslam::bench {

struct TruePerson {
  cv::Rect box;          ///< amodal, clipped to the image
  bool counted = false;  ///< at least min_visible visible
};

/// One-to-one pairs (index in `detected`, index in `truth`) of boxes overlapping at IoU >=
/// `min_iou`, the largest overlaps first (the greedy matching of PASCAL VOC and COCO).
std::vector<std::pair<size_t, size_t>> matchBoxes(const std::vector<cv::Rect>& detected,
                                                  const std::vector<cv::Rect>& truth,
                                                  double min_iou = 0.5);

/// A true object's box and category, for matchDetections.
struct TrueBox {
  cv::Rect box;
  std::string category;
};

/// For each detection, the index in `truth` of the box of its own category it is matched to
/// (matchBoxes within each category), or -1.
std::vector<int> matchDetections(const std::vector<core::Detection>& detections,
                                 const std::vector<TrueBox>& truth, double min_iou = 0.5);

/// objects.txt's people by frame.
std::map<std::size_t, std::vector<TruePerson>> readTruePeople(const std::string& objects_txt,
                                                              double min_visible);

struct DetectionScore {
  std::size_t found = 0, missed = 0, false_positives = 0;
  double recall() const { return found + missed ? double(found) / double(found + missed) : 0; }
  double precision() const {
    return found + false_positives ? double(found) / double(found + false_positives) : 0;
  }
};

/// `detector` on `frames` (each frame's index is its frame in objects.txt); with `draw_dir`, each
/// frame with its true and detected boxes is written there as detections_NNNNNN.png.
DetectionScore scoreDetector(detection::Detector& detector, const std::vector<core::Frame>& frames,
                             const std::map<std::size_t, std::vector<TruePerson>>& truth,
                             const std::string& draw_dir = "");

}  // namespace dynslam::bench
