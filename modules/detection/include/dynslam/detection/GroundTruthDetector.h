#pragma once
// Boxes from the simulator's ground truth (dynslam-sim's objects.txt), degraded on purpose to
// behave like a real detector: objects too hidden to be seen are not reported, some visible ones
// are missed, box edges jitter, and boxes appear where nothing is. Frames are matched to the file
// by stamp (its t column is the rawlog stamp); the noise of a frame depends on the seed and the
// frame's index alone, so runs repeat and do not depend on which frames were detected before.
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/detection/ClassMap.h>
#include <dynslam/detection/Detector.h>

#include <cstdint>
#include <memory>
#include <string>

namespace dynslam::detection {

/// `objects` names a file, or `feed:NAME` an in-process core::ObjectGroundTruthFeed.
/// Keys, ranges, meanings: DetectionOptions::describe() in DetectionOptions.cpp;
/// docs/parameters.md.
struct GroundTruthDetectorSettings {
  std::string objects;
  double miss_rate = 0.0;
  double jitter_px = 0.0;
  double false_positive_rate = 0.0;
  /// An object with no visible pixel is never reported, whatever this says.
  double min_visible_fraction = 0.2;
  int seed = 1;
  /// s; how far a frame's stamp may be from the file's (MRPT stores stamps in 100 ns ticks).
  /// Not an ini key.
  double time_tolerance = 1e-3;
};

class GroundTruthDetector : public Detector {
 public:
  /// Reads the objects file (core::ObjectGroundTruthError naming it when it cannot be read);
  /// throws DetectorError when a class in it is not a COCO class name the class map can look up.
  GroundTruthDetector(GroundTruthDetectorSettings settings, ClassMap class_map);

  /// Throws DetectorError when the frame's stamp is more than a second outside the file's time
  /// span: the file belongs to another sequence.
  std::vector<core::Detection> detect(const core::Frame& frame) override;

 private:
  GroundTruthDetectorSettings settings_;
  ClassMap class_map_;
  core::ObjectGroundTruthIndex index_;
  /// `objects = feed:NAME`: rows added while the run goes on (a closed-loop simulation), whose
  /// classes cannot be checked up front.
  std::shared_ptr<core::ObjectGroundTruthFeed> feed_;
  double first_t_ = 0, last_t_ = 0;
};

}  // namespace dynslam::detection
