#pragma once
// Detection accuracy against a simulated sequence's objects.txt: a frame's person detections
// matched one to one with its true people (box IoU >= 0.5, largest first). People at least
// `min_visible` visible must be found (a miss counts against recall); a detection on a less
// visible person is neither right nor wrong; any other detection is a false positive.
#include <dynslam/core/Frame.h>
#include <dynslam/detection/Detector.h>

#include <map>
#include <string>
#include <vector>

namespace dynslam::bench {

struct TruePerson {
  cv::Rect box;          ///< amodal, clipped to the image
  bool counted = false;  ///< at least min_visible visible
};

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

/// `detector` on `frames` (each frame's index is its frame in objects.txt).
DetectionScore scoreDetector(detection::Detector& detector, const std::vector<core::Frame>& frames,
                             const std::map<std::size_t, std::vector<TruePerson>>& truth);

}  // namespace dynslam::bench
