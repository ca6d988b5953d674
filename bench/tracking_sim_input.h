#pragma once
// The simulated input of bench-tracking: the scenario rendered in-process, detections from
// GroundTruthDetector (which reads the ground truth from an objects.txt written to a temporary
// folder, as it would read dynslam-sim's) or from YOLOX-nano, object depth from the segmentation,
// the true depth or the box median, and the truth boxes the tracks are scored against; cached per
// frame so the tracker can be run many times (sweeps) on the same input.
#include <dynslam/evaluation/MotMetrics.h>
#include <dynslam/tracking/KalmanBoxTracker.h>

#include <opencv2/core/types.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dynslam::bench {

struct BenchSettings {
  std::string config = "params/sim/indoor_people_high.ini";
  size_t frames = 0;  // 0: all
  double miss_rate = 0.1, jitter = 3.0, min_visible = 0.2;
  uint32_t seed = 1;
  /// "truth": GroundTruthDetector with miss_rate and jitter; "yolox": YOLOX-nano (`model`) on the
  /// rendered colour, each box given the truth it overlaps at IoU >= 0.5.
  std::string detector = "truth";
  std::string model = "../shared/models/yolox_nano.onnx";
  std::string depth = "segmentation";
  /// --system INI: its [Tracking] and [Segmentation] as the start ("": the bench's own start).
  std::string system_ini;
  /// --true-depth-below V (with depth "segmentation"; 0 = off): a detection of a person less
  /// than V visible takes the true depth instead of the segmentation's (no d_alt), and its
  /// descriptor is taken in the band of that depth: how much of the gap between the two depths
  /// the partly hidden people make.
  double true_depth_below = 0;
  int report_coasting = 1;
  bool identities = false;                // print which tracks covered each truth id
  int trace_first = -1, trace_last = -1;  // --trace A-B: print the tracker's frames A..B
  std::string sweep = "Tracking.rho_min=0.3,0.5,0.6,0.7,0.8";  // "": none
  std::vector<std::string> sim_overrides, tracker_overrides;
  std::vector<std::string> segmentation_overrides;  // "Segmentation.key=value" (--set)
};

/// How the depth was given, for the printouts: "segmentation", "truth", "box", or
/// "segmentation (true below 0.60 visible)".
std::string depthSource(const BenchSettings& s);

/// The truth behind one observation; a false positive keeps the defaults.
struct ObservationTruth {
  int id = -1;         // the truth id
  double depth = 0;    // the true object depth, m
  double visible = 0;  // the visible fraction
};

/// What the tracker sees and what it is scored against, per frame.
struct CachedFrame {
  double t = 0;
  std::vector<tracking::BoxObservation> observations;
  std::vector<ObservationTruth> observation_truth;  // one per observation
  std::vector<evaluation::MotTruthBox> truth;
};

struct CachedRun {
  cv::Size image;
  std::vector<CachedFrame> frames;
  size_t people = 0;
  std::vector<double> selfRho;  // depth IoU of each counted truth box with its previous one
};

/// Renders the scenario twice (ground truth, then images for detection and segmentation) and
/// returns what the tracker sees and what it is scored against, per frame.
CachedRun prepareSimulatedRun(const BenchSettings& s);

}  // namespace dynslam::bench
