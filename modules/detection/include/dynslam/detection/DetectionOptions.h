#pragma once
// The [Detection] section: which detector, how it runs, the class map, and the keys of the chosen
// detector only (a key of another detector is an unknown-key error, not a silently dead one).
#include <dynslam/detection/GroundTruthDetector.h>
#include <dynslam/detection/HogPeopleDetector.h>
#include <dynslam/detection/OnnxYoloDetector.h>

#include <dynslam/core/Options.h>

#include <string>
#include <vector>

namespace dynslam::detection {

/// [Detection]: every key, its range and meaning in describe() (DetectionOptions.cpp);
/// docs/parameters.md. describe() lists `detector` first, then the keys of the detector it
/// names only.
struct DetectionOptions : core::Options {
  /// The words of `detector`; each names one of the settings structs below.
  static const std::vector<std::string> kDetectors;

  std::string detector = "onnx_yolo";
  std::string mode = "deterministic";
  std::string class_map;  ///< ClassMap()'s default, set by the constructor
  OnnxYoloDetectorSettings onnx_yolo;
  HogPeopleDetectorSettings hog;
  GroundTruthDetectorSettings ground_truth;

  DetectionOptions();

  void describe(core::OptionVisitor& v) override;
};

}  // namespace dynslam::detection
