#include "tracking_sim_input.h"

#include "detection_accuracy.h"

#include <dynslam/core/Config.h>
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/detection/GroundTruthDetector.h>
#include <dynslam/detection/OnnxYoloDetector.h>
#include <dynslam/segmentation/DepthThresholdSegmenter.h>
#include <dynslam/segmentation/MaskQuality.h>
#include <dynslam/segmentation/SegmentationStage.h>
#include <dynslam/sim/MakeSequence.h>
#include <dynslam/tracking/Appearance.h>
#include <dynslam/tracking/DepthIoU.h>

#include <unistd.h>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

namespace dynslam::bench {

std::string depthSource(const BenchSettings& s) {
  if (!(s.true_depth_below > 0)) return s.depth;
  char label[96];
  std::snprintf(label, sizeof label, "%s (true below %.2f visible)", s.depth.c_str(),
                s.true_depth_below);
  return label;
}

namespace {

/// The object's true depth as the segmentation should measure it: the median depth of its
/// visible pixels (as bench-segmentation scores d_t), else its torso's depth.
double trueDepth(const sim::SimFrame& f, const sim::ObjectTruth& o) {
  const double visible = segmentation::visibleMedianDepth(f.image.depth, f.image.label, o.id);
  if (visible > 0) return visible;
  return (f.T_world_camera.inverse() * o.T_world_object).translation().z();
}

/// objects.txt as dynslam-sim writes it (SimulationWriter), with t in seconds from the start.
std::string writeObjects(const sim::Sequence& simulator, size_t frames, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/objects.txt";
  std::ofstream out(path);
  out << core::kObjectGroundTruthHeader;
  sim::SimFrame f;
  for (size_t i = 0; i < frames; ++i) {
    simulator.renderFrame(i, f);
    for (const auto& o : f.objects)
      core::writeObjectGroundTruthRow(out, sim::groundTruthRow(i, f.t, o));
  }
  return path;
}

/// A folder of its own for each call: --jobs prepares several runs at once in one process.
std::string runFolder() {
  static std::atomic<int> calls{0};
  return (std::filesystem::temp_directory_path() /
          ("bench-tracking-" + std::to_string(getpid()) + "-" + std::to_string(calls++)))
      .string();
}

/// The segmentation exactly as the pipeline's Segmentation stage reads it from --set.
segmentation::DepthThresholdParams segmentationParams(const BenchSettings& s) {
  auto segIni = s.system_ini.empty() ? core::IniConfig::fromText("", "bench-tracking --set")
                                     : core::IniConfig::fromFile(s.system_ini, {});
  for (const auto& o : s.segmentation_overrides) segIni.applyOverride(o);
  segmentation::SegmentationStage segStage;
  segStage.configure(segIni, "Segmentation");
  return segStage.options().params;
}

/// Appends to `selfRho` the depth IoU of each object counted on frame `sf` with its own box and
/// depth on the frame before (`previous`: truth id -> box, depth; then replaced by this frame's).
void noteSelfRho(const sim::SimFrame& sf, double minVisible,
                 std::map<int, std::pair<cv::Rect2f, double>>& previous,
                 std::vector<double>& selfRho) {
  std::map<int, std::pair<cv::Rect2f, double>> current;
  for (const auto& o : sf.objects) {
    if (o.visible_pixels == 0 || o.visible_fraction < minVisible) continue;
    current[o.id] = {cv::Rect2f(o.box), trueDepth(sf, o)};
    const auto it = previous.find(o.id);
    if (it != previous.end())
      selfRho.push_back(tracking::depthIoU(it->second.first, it->second.second, current[o.id].first,
                                           current[o.id].second));
  }
  previous = std::move(current);
}

/// frame.object_masks as --depth asks: the segmentation's, one with the true depth per
/// detection, or none ("box": the tracker's fallback).
void addObjectMasks(core::Frame& frame, const sim::SimFrame& sf, const BenchSettings& s,
                    const segmentation::DepthThresholdSegmenter& segmenter) {
  if (s.depth == "segmentation") {
    frame.object_masks = segmenter.segment(frame.depth, frame.detections, {}, frame.intrinsics.fy);
  } else if (s.depth == "truth") {
    for (size_t k = 0; k < frame.detections.size(); ++k)
      for (const auto& o : sf.objects)
        if (o.id == frame.detections[k].truth_id) {
          core::ObjectMask m;
          m.detection = int(k);
          m.valid = true;
          m.d_t = trueDepth(sf, o);
          frame.object_masks.push_back(m);
        }
  }
}

/// The observations of `frame`'s detections and the truth behind each (--true-depth-below gives
/// the partly hidden ones their true depth and the descriptor at it).
void addObservations(CachedFrame& c, const core::Frame& frame, const sim::SimFrame& sf,
                     const BenchSettings& s) {
  for (size_t k = 0; k < frame.detections.size(); ++k) {
    const auto& d = frame.detections[k];
    c.observations.push_back(tracking::observeDetection(frame, k, /*withAppearance=*/true));
    bench::ObservationTruth truth;
    if (d.truth_id > 0) truth.id = int(d.truth_id);
    for (const auto& o : sf.objects)
      if (o.id == d.truth_id) {
        truth.depth = trueDepth(sf, o);
        truth.visible = o.visible_fraction;
      }
    if (truth.depth > 0 && truth.visible < s.true_depth_below) {
      tracking::BoxObservation& partlyHidden = c.observations.back();
      partlyHidden.depth = truth.depth;
      partlyHidden.depth_alt = 0;
      partlyHidden.appearance = tracking::bodyHistogram(frame.rgb, d.box, frame.depth, truth.depth);
    }
    c.observation_truth.push_back(truth);
  }
}

/// appearance_at for the observations given another's surface: the tracker reads it
/// (reid_at_track_depth) of these only; each keeps a copy of its box's pixels, not the frame,
/// so that the cache of 900 frames stays small.
void addAppearanceAt(CachedFrame& c, const core::Frame& frame) {
  for (size_t k = 0; k < c.observations.size(); ++k)
    if (tracking::givenAnothersSurface(c.observations, k)) {
      const cv::Rect2f& b = frame.detections[k].box;
      const cv::Rect roi =
          cv::Rect(cvFloor(b.x) - 1, cvFloor(b.y) - 1, cvCeil(b.width) + 3, cvCeil(b.height) + 3) &
          cv::Rect(0, 0, frame.rgb.cols, frame.rgb.rows);
      const cv::Rect2f box = b - cv::Point2f(float(roi.x), float(roi.y));
      c.observations[k].appearance_at = [rgb = frame.rgb(roi).clone(),
                                         depth = frame.depth(roi).clone(), box](double d) {
        return tracking::bodyHistogram(rgb, box, depth, d);
      };
    }
}

/// Each detection of `frame` of a true object gets its id: the one its box overlaps at IoU >= 0.5
/// among the visible objects of its category (YOLOX-nano knows no truth).
void assignTruth(core::Frame& frame, const sim::SimFrame& sf) {
  std::vector<bench::TrueBox> truth;
  std::vector<uint16_t> ids;
  for (const auto& o : sf.objects)
    if (o.visible_pixels > 0) truth.push_back({o.box, o.category}), ids.push_back(o.id);
  const std::vector<int> matched = bench::matchDetections(frame.detections, truth);
  for (size_t k = 0; k < matched.size(); ++k)
    if (matched[k] >= 0) frame.detections[k].truth_id = ids[size_t(matched[k])];
}

/// The detector --detector names.
std::unique_ptr<detection::Detector> makeDetector(const BenchSettings& s,
                                                  const sim::Sequence& sequence, size_t frames,
                                                  const std::string& dir) {
  if (s.detector == "yolox") {
    detection::OnnxYoloDetectorSettings yolo;
    yolo.model = s.model;
    return std::make_unique<detection::OnnxYoloDetector>(yolo, detection::ClassMap());
  }
  detection::GroundTruthDetectorSettings gt;
  gt.objects = writeObjects(sequence, frames, dir);
  gt.miss_rate = s.miss_rate;
  gt.jitter_px = s.jitter;
  gt.min_visible_fraction = s.min_visible;
  gt.seed = s.seed;
  return std::make_unique<detection::GroundTruthDetector>(gt, detection::ClassMap());
}

}  // namespace

CachedRun prepareSimulatedRun(const BenchSettings& s) {
  sim::ScenarioOptions options;
  options.load(core::IniConfig::fromFile(s.config, s.sim_overrides));
  const std::unique_ptr<sim::Sequence> sequence = sim::makeSequence(options);
  const size_t frames =
      s.frames ? std::min(s.frames, sequence->frameCount()) : sequence->frameCount();
  const std::string dir = runFolder();
  const std::unique_ptr<detection::Detector> detector = makeDetector(s, *sequence, frames, dir);
  const segmentation::DepthThresholdSegmenter segmenter(segmentationParams(s));

  CachedRun run;
  run.image = cv::Size(sequence->camera().width, sequence->camera().height);
  run.people = size_t(options.people.walkers + options.people.standing);
  sim::SimFrame sf;
  std::map<int, std::pair<cv::Rect2f, double>> previous;  // truth id -> box, depth
  for (size_t i = 0; i < frames; ++i) {
    sequence->renderFrame(i, sf);
    noteSelfRho(sf, s.min_visible, previous, run.selfRho);
    core::Frame frame;
    frame.index = i;
    frame.t = sf.t;
    frame.rgb = sf.image.rgb;
    frame.depth = sf.image.depth;
    frame.intrinsics = sequence->camera();
    frame.detections = detector->detect(frame);
    if (s.detector == "yolox") assignTruth(frame, sf);
    addObjectMasks(frame, sf, s, segmenter);
    CachedFrame c;
    c.t = frame.t;
    addObservations(c, frame, sf, s);
    addAppearanceAt(c, frame);
    for (const auto& o : sf.objects)
      c.truth.push_back({int(o.id), cv::Rect2d(o.box),
                         o.visible_pixels > 0 && o.visible_fraction >= s.min_visible});
    run.frames.push_back(std::move(c));
  }
  std::filesystem::remove_all(dir);
  return run;
}

}  // namespace dynslam::bench
