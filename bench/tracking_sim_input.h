#pragma once
// The simulated input of bench-tracking: the scenario rendered in-process, detections from
// GroundTruthDetector (which reads the ground truth from an objects.txt written to a temporary
// folder, as it would read dynslam-sim's), object depth from the segmentation, the true depth or
// the box median, and the truth boxes the tracks are scored against; cached per frame so the
// tracker can be run many times (sweeps) on the same input.
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
  std::string depth = "segmentation";
  int report_coasting = 1;
  bool identities = false;  // print which tracks covered each truth id
  int trace_first = -1, trace_last = -1;  // --trace A-B: print the tracker's frames A..B
  std::string sweep = "Tracking.rho_min=0.3,0.5,0.6,0.7,0.8";  // "": none
  std::vector<std::string> sim_overrides, tracker_overrides;
  std::vector<std::string> segmentation_overrides;  // "Segmentation.key=value" (--set)
};

/// What the tracker sees and what it is scored against, per frame.
struct CachedFrame {
  double t = 0;
  std::vector<tracking::BoxObservation> observations;
  std::vector<int> observation_truth;  // the truth id of each observation (-1: false positive)
  std::vector<double> observation_true_depth;  // its true object depth, m (0: false positive)
  std::vector<double> observation_visible;     // its truth's visible fraction (0: false positive)
  std::vector<evaluation::MotTruthBox> truth;
};

struct CachedRun {
  cv::Size image;
  std::vector<CachedFrame> frames;
  size_t people = 0;
  std::vector<double> depthErrors;  // |d - d_true| / d_true of the observations
  std::vector<double> selfRho;      // depth IoU of each counted truth box with its previous one
};

/// Renders the scenario twice (ground truth, then images for detection and segmentation) and
/// returns what the tracker sees and what it is scored against, per frame.
CachedRun prepareSimulatedRun(const BenchSettings& s);

}  // namespace dynslam::bench
