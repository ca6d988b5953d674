#pragma once
// The [Detection] section: which detector, how it runs, the class map, and the keys of the chosen
// detector only (a key of another detector is an unknown-key error, not a silently dead one).
#include <dynslam/detection/GroundTruthDetector.h>
#include <dynslam/detection/HogPeopleDetector.h>
#include <dynslam/detection/OnnxYoloDetector.h>

#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace dynslam::detection {

struct DetectionOptions : mrpt::config::CLoadableOptions {
  std::string detector = "onnx_yolo";  ///< onnx_yolo | hog | ground_truth
  std::string mode = "deterministic";  ///< deterministic | realtime
  std::string class_map;               ///< ClassMap.h's ini form; set to ClassMap()'s default
  OnnxYoloDetectorSettings onnx_yolo;
  HogPeopleDetectorSettings hog;
  GroundTruthDetectorSettings ground_truth;

  DetectionOptions();

  /// Reads `detector` and then the keys of that detector only.
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  /// Writes the common keys and those of the detector `detector` names.
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace dynslam::detection
