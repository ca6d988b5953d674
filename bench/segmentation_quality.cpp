// Depth-threshold segmentation (method.md section 1) against the simulator's ground truth,
// with the ground-truth boxes as detections (issue 4's targets):
//   - mean mask IoU against the instance labels, people at least half visible: >= 0.80
//   - object depth d_t within 5 % of the true depth under mild (visible 0.5-0.9) and severe
//     (< 0.5) occlusion (paper Table 2: 1-5 %, "occlusion among the targets", so of people a
//     detector still reports); true depth = median depth of the person's visible pixels (the
//     surface the camera sees); the torso centre's z is shown beside it
//   - segmentation time per frame, median: <= 1.2 ms with about 3 objects (paper Table 1)
// --pipeline INI (not the method) scores the masks the system itself ends a frame with: INI's
// [Segmentation], then [Tracking] (every frame), then [Retrack] (boxes = tracked_detections:
// each detection segmented again, its cluster chosen by the depth of the track that took it),
// as `dynslam` runs them with params/sim_frontend.ini; time is then that of all three stages.
// --seg-config INI takes INI's [Segmentation] only (each frame alone, as without --pipeline):
// the first stage of a system ini, without copying its keys into --seg-set.
// Detections: the people and cars at least --min-visible visible (default: the share below which
// the system's GroundTruthDetector reports nothing, 0.2, as a real detector misses a person
// hidden that much); --min-visible 0 gives every object with a visible pixel a box. --boxes yolox
// takes YOLOX-nano's boxes instead (the real detector's masks; its misses counted apart).
// Precision (mask pixels that are the person) and recall (the person's pixels in the mask)
// tell over- from under-segmentation; "box as mask" is the IoU a mask filling the whole box
// would score. --dump DIR writes the worst masks as images (green: right, red: not the person,
// blue: missed). --cases FILE writes one CSV row per scored person (its d_t, the clusters, and
// the other overlapping object whose visible depth is nearest d_t: whose surface it took).
//
//   build/bin/bench-segmentation [--config params/sim/A.ini]... [--every 3] [--set s.k=v]...
//        [--seg-set Segmentation.key=value]... [--boxes amodal|visible|yolox] [--min-visible 0.2]
//        [--dump DIR] [--dump-max 12] [--pipeline params/sim_frontend.ini] [--cases FILE.csv]
//        [--seg-config params/sim_vio.ini]
// Without --config: indoor_people_high. An augment scene (params/sim/augmented_7scenes.ini, with
// --set Augment.rawlog=...) is scored the same way: the inserted movers' boxes and instance
// labels against the real depth they are composited into (real pixels are label 0).
#include "detection_accuracy.h"
#include "segmentation_failure_images.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/Median.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/detection/GroundTruthDetector.h>
#include <dynslam/detection/OnnxYoloDetector.h>
#include <dynslam/segmentation/FloorRemovalStage.h>
#include <dynslam/segmentation/MaskQuality.h>
#include <dynslam/segmentation/SegmentationStage.h>
#include <dynslam/sim/MakeSequence.h>
#include <dynslam/tracking/TrackingStage.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace dynslam;

double mean(const std::vector<double>& v) {
  return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}
double fractionBelow(const std::vector<double>& v, double bound) {
  return v.empty()
             ? 0
             : double(std::count_if(v.begin(), v.end(), [&](double x) { return x <= bound; })) /
                   v.size();
}

enum Occlusion { None, Mild, Severe };
const char* kOcclusionName[] = {"none (visible >= 0.9)", "mild (0.5-0.9)", "severe (< 0.5)"};

struct Scores {
  std::vector<double> iou, precision, recall, boxIoU;
  std::vector<double> iouRightDepth;  // IoU of the masks whose d_t is within 5 %
  std::vector<double> iouAlone;       // IoU without step 9 (each box segmented alone)
  size_t behind[3] = {0, 0, 0}, inFront[3] = {0, 0, 0};  // d_t off the person by more than e
  std::vector<double> depthErr[3], torsoErr[3];          // |d_t - truth| / truth, %
  std::vector<double> ms, objects;                       // per frame
  size_t invalid = 0, seen = 0, outOfRange = 0;  // seen: objects of the kind, any visibility
  // Pixels of the scored people (>= 50 % visible): visible, and where the missed ones went;
  // mask pixels that are not the person's.
  size_t visible = 0, missedNoDepth = 0, missedOutsideRange = 0, missedToOther = 0;
  size_t maskOther = 0, maskBackground = 0, maskObject = 0;
};

/// Adds to `s` where person `id`'s visible pixels went that mask `m` missed (no depth, depth
/// outside [t_min, t_max], or in range but given to another object by the mutual-occlusion
/// step) and what `m` holds that is not the person (background, another object).
void tallyPixels(const cv::Mat& label, const cv::Mat& depth, uint16_t id, const core::ObjectMask& m,
                 Scores& s) {
  for (int y = 0; y < label.rows; ++y)
    for (int x = 0; x < label.cols; ++x) {
      const uint16_t l = label.at<uint16_t>(y, x);
      const bool inMask =
          m.valid && m.roi.contains({x, y}) && m.mask.at<uint8_t>(y - m.roi.y, x - m.roi.x) != 0;
      if (l == id) {
        ++s.visible;
        if (inMask) continue;
        const float z = depth.at<float>(y, x);
        if (!(z > 0))
          ++s.missedNoDepth;
        else if (z < m.t_min || z > m.t_max)
          ++s.missedOutsideRange;
        else
          ++s.missedToOther;
      } else if (inMask) {
        ++(l == 0 ? s.maskBackground : s.maskOther);
      }
    }
  s.maskObject += m.valid ? cv::countNonZero(m.mask) : 0;
}

void printTable(const Scores& s, bool pipeline) {
  const double iou = mean(s.iou);
  std::printf(
      "  mask IoU, people >= 50 %% visible (%zu): mean %.3f, median %.3f  [target >= 0.80:"
      " ratio %.2f, %s]\n",
      s.iou.size(), iou, dynslam::core::upperMedian(s.iou), iou / 0.80,
      iou >= 0.80 ? "met" : "MISSED");
  std::printf("    precision %.3f, recall %.3f (means); box as mask: IoU %.3f\n", mean(s.precision),
              mean(s.recall), mean(s.boxIoU));
  std::printf("    where d_t is within 5 %% of the truth (%zu of %zu): mean IoU %.3f\n",
              s.iouRightDepth.size(), s.iou.size(), mean(s.iouRightDepth));
  std::printf("    each box alone (no mutual-occlusion step): mean IoU %.3f\n", mean(s.iouAlone));
  const double v = std::max<size_t>(1, s.visible), a = std::max<size_t>(1, s.maskObject);
  std::printf(
      "    their visible pixels missed: %.1f %% outside [T_min, T_max], %.1f %% in range but "
      "given to another object, %.1f %% without depth; mask pixels not theirs: %.1f %% "
      "background, %.1f %% another object\n",
      100 * s.missedOutsideRange / v, 100 * s.missedToOther / v, 100 * s.missedNoDepth / v,
      100 * s.maskBackground / a, 100 * s.maskOther / a);
  std::printf(
      "  d_t error, %% of the true depth       mean  median  <=5%%  behind  in front  "
      "vs torso z  target\n");
  for (int c = None; c <= Severe; ++c) {
    const auto& e = s.depthErr[c];
    const bool targeted = c != None;
    const double n = std::max<size_t>(1, e.size());
    std::printf("    %-22s (%4zu)  %6.2f  %6.2f  %3.0f%%  %4.0f%%   %4.0f%%     %6.2f      %s\n",
                kOcclusionName[c], e.size(), mean(e), dynslam::core::upperMedian(e),
                100 * fractionBelow(e, 5.0), 100 * s.behind[c] / n, 100 * s.inFront[c] / n,
                mean(s.torsoErr[c]),
                !targeted        ? "-"
                : mean(e) <= 5.0 ? "mean <= 5 %: met"
                                 : "mean <= 5 %: MISSED");
  }
  std::printf("    (behind / in front: d_t more than e = 0.5 m beyond / before the true depth)\n");
  std::printf(
      "  people seen: %zu; with no depth on any visible pixel (beyond range, not scored): "
      "%zu; masks without enough depth: %zu\n",
      s.seen, s.outOfRange, s.invalid);
  std::vector<double> three;
  for (size_t i = 0; i < s.ms.size(); ++i)
    if (s.objects[i] == 3) three.push_back(s.ms[i]);
  const double t = dynslam::core::upperMedian(s.ms);
  std::printf(
      "  time per frame%s: median %.3f ms (%.1f objects/frame on average), median %.3f ms "
      "over the %zu frames with 3 objects",
      pipeline ? ", every --pipeline stage" : "", t, mean(s.objects),
      dynslam::core::upperMedian(three), three.size());
  // The 1.2 ms target is one segmentation's; --pipeline times Segmentation, Tracking (with its
  // colour histograms), Segmentation:Retrack and FloorRemoval when listed, together.
  if (pipeline)
    std::printf(
        "  [the 1.2 ms target is one segmentation stage's: run without --pipeline, or "
        "read bench-classification's per-stage medians]\n");
  else
    std::printf("  [target <= 1.2 ms: ratio %.2f, %s]\n", t / 1.2, t <= 1.2 ? "met" : "MISSED");
}

/// One --cases row: person `o` (true visible depth `z`) and its mask `m`; the other object
/// whose box overlaps `o`'s and whose visible depth is nearest d_t, and whether it was detected.
void writeCase(std::ostream& out, const std::string& scenario, size_t frame,
               const sim::ObjectTruth& o, double z, const core::ObjectMask& m, double err,
               const sim::SimFrame& f, const std::vector<core::Detection>& detections,
               double trackDepth) {
  const sim::ObjectTruth* other = nullptr;
  double otherZ = 0;
  for (const auto& q : f.objects) {
    if (q.id == o.id || q.visible_pixels == 0 || (q.box & o.box).empty()) continue;
    const double qz = segmentation::visibleMedianDepth(f.image.depth, f.image.label, q.id);
    if (qz > 0 && (!other || std::abs(qz - m.d_t) < std::abs(otherZ - m.d_t))) {
      other = &q;
      otherZ = qz;
    }
  }
  const bool otherDetected =
      other && std::any_of(detections.begin(), detections.end(),
                           [&](const core::Detection& d) { return d.truth_id == other->id; });
  out << scenario << ',' << frame << ',' << o.id << ',' << o.visible_fraction << ',' << z << ','
      << m.d_t << ',' << m.d_alt << ',' << m.d_o << ',' << m.d_b << ',' << err << ','
      << (other ? other->id : -1) << ',' << otherZ << ',' << (other ? other->visible_fraction : 0.0)
      << ',' << otherDetected << ',' << trackDepth << '\n';
}

/// Cars (no target in the issue; the front-end's car features depend on them): mask IoU of
/// those at least half visible and the d_t error.
void printCars(const Scores& s) {
  std::printf(
      "  cars seen %zu: mask IoU (>= 50 %% visible, %zu) mean %.3f, median %.3f, precision %.3f, "
      "recall %.3f; beyond range %zu, masks without enough depth %zu\n",
      s.seen, s.iou.size(), mean(s.iou), dynslam::core::upperMedian(s.iou), mean(s.precision),
      mean(s.recall), s.outOfRange, s.invalid);
  const double a = std::max<size_t>(1, s.maskObject);
  std::printf("    car mask pixels not the car: %.1f %% background, %.1f %% another object\n",
              100 * s.maskBackground / a, 100 * s.maskOther / a);
  for (int c = None; c <= Severe; ++c)
    std::printf("    d_t error, %-22s (%4zu): mean %6.2f %%, median %6.2f %%\n", kOcclusionName[c],
                s.depthErr[c].size(), mean(s.depthErr[c]),
                dynslam::core::upperMedian(s.depthErr[c]));
}

/// The perception stages of a pipeline ini after Detection (--pipeline): Segmentation,
/// Tracking, Segmentation:Retrack, and FloorRemoval when its [pipeline] stages list it. One
/// instance per scenario: the tracker keeps state.
class PerceptionStages {
 public:
  explicit PerceptionStages(const core::IniConfig& cfg) {
    segmentation_.configure(cfg, "Segmentation");
    tracking_.configure(cfg, "Tracking");
    retrack_.configure(cfg, "Retrack");
    if (retrack_.options().boxes != segmentation::SegmentedBoxes::TrackedDetections)
      throw core::UsageError("--pipeline: [Retrack] boxes must be tracked_detections");
    for (const auto& e : core::pipelineStageEntries(cfg))
      if (e.class_name == "FloorRemoval") {
        floor_.emplace();
        floor_->configure(cfg, e.section);
      }
  }
  /// The depth of the track that took each detection of the last frame (0: none).
  const std::vector<double>& trackDepth() const { return trackDepth_; }
  /// The stages run, for the report: "Segmentation, Tracking and Retrack[ and FloorRemoval]".
  std::string names() const {
    return floor_ ? "Segmentation, Tracking, Retrack and FloorRemoval"
                  : "Segmentation, Tracking and Retrack";
  }
  /// The detections' masks (one per detection, in order) at the end of the three stages.
  std::vector<core::ObjectMask> masks(const sim::SimFrame& f,
                                      const std::vector<core::Detection>& detections,
                                      const core::CameraIntrinsics& intrinsics) {
    core::Frame frame;
    frame.t = f.t;
    frame.intrinsics = intrinsics;
    frame.rgb = f.image.rgb;
    frame.depth = f.image.depth;
    frame.detections = detections;
    frame.detections_fresh = true;
    segmentation_.process(frame);
    tracking_.process(frame);
    retrack_.process(frame);
    if (floor_) floor_->process(frame);
    std::vector<core::ObjectMask> out(detections.size());
    for (const auto& m : frame.object_masks)
      if (m.detection >= 0 && size_t(m.detection) < out.size()) out[size_t(m.detection)] = m;
    trackDepth_.assign(detections.size(), 0.0);
    for (const auto& t : frame.tracks)
      if (t.detection >= 0 && size_t(t.detection) < out.size())
        trackDepth_[size_t(t.detection)] = t.depth;
    return out;
  }

 private:
  segmentation::SegmentationStage segmentation_, retrack_;
  tracking::TrackingStage tracking_;
  std::optional<segmentation::FloorRemovalStage> floor_;
  std::vector<double> trackDepth_;
};

/// The detections a frame gives: the people and cars at least `minVisible` visible (hidden that
/// much, no detector reports them; wholly hidden: never), with the truth of each.
struct FrameDetections {
  std::vector<core::Detection> detections;
  std::vector<const sim::ObjectTruth*> truths;
};

/// Where a frame's detections come from (--boxes): the truth's amodal or visible boxes, or
/// YOLOX-nano on the rendered colour, each of its boxes given the truth it overlaps at IoU >= 0.5
/// (matchBoxes; one without stays unscored, a person without one is a detector's miss).
class BoxSource {
 public:
  BoxSource(std::string mode, double minVisible, const std::string& model)
      : mode_(std::move(mode)), minVisible_(minVisible) {
    if (mode_ != "amodal" && mode_ != "visible" && mode_ != "yolox")
      throw core::UsageError("--boxes " + mode_ + ": expected amodal, visible or yolox");
    if (mode_ == "yolox") {
      detection::OnnxYoloDetectorSettings settings;
      settings.model = model;
      yolo_ = std::make_unique<detection::OnnxYoloDetector>(settings, detection::ClassMap());
    }
  }

  const std::string& mode() const { return mode_; }
  double minVisible() const { return minVisible_; }

  FrameDetections of(const sim::SimFrame& f, const core::CameraIntrinsics& camera) {
    return yolo_ ? detected(f, camera) : truthBoxes(f);
  }

  /// With yolox: the people at least half visible on the frames given, and how many of them a
  /// detection was matched to.
  size_t halfVisiblePeople = 0, halfVisibleFound = 0;

 private:
  FrameDetections truthBoxes(const sim::SimFrame& f) const {
    FrameDetections out;
    for (const auto& o : f.objects) {
      if (o.visible_pixels == 0 || o.visible_fraction < minVisible_) continue;
      core::Detection d;
      // amodal: the simulator's box (the whole body, hidden parts too); visible: the box
      // round the visible pixels, as a detector that sees only those might draw it.
      d.box = mode_ == "visible" ? cv::boundingRect(f.image.label == o.id) : o.box;
      d.category = o.category;
      d.model = o.category == "car" ? core::MotionModel::Rigid : core::MotionModel::NonRigid;
      d.truth_id = o.id;
      out.detections.push_back(d);
      out.truths.push_back(&o);
    }
    return out;
  }

  FrameDetections detected(const sim::SimFrame& f, const core::CameraIntrinsics& camera) {
    core::Frame frame;
    frame.index = f.index;
    frame.rgb = f.image.rgb;
    frame.depth = f.image.depth;
    frame.intrinsics = camera;
    FrameDetections out;
    out.detections = yolo_->detect(frame);
    out.truths.assign(out.detections.size(), nullptr);
    std::vector<bench::TrueBox> truth;
    std::vector<const sim::ObjectTruth*> objects;
    for (const auto& o : f.objects)
      if (o.visible_pixels > 0) truth.push_back({o.box, o.category}), objects.push_back(&o);
    const std::vector<int> matched = bench::matchDetections(out.detections, truth);
    for (size_t k = 0; k < matched.size(); ++k)
      if (matched[k] >= 0) {
        out.truths[k] = objects[size_t(matched[k])];
        out.detections[k].truth_id = out.truths[k]->id;
      }
    for (const auto& o : f.objects)
      if (o.category == "person" && o.visible_fraction >= 0.5) {
        ++halfVisiblePeople;
        halfVisibleFound += std::count(out.truths.begin(), out.truths.end(), &o);
      }
    return out;
  }

  std::string mode_;
  double minVisible_;
  std::unique_ptr<detection::Detector> yolo_;
};

/// Scores the masks of people (the issue's targets) and cars (printed apart) against the
/// simulator's truth, frame by frame.
class MaskScorer {
 public:
  Scores people, cars;  // the frame figures (ms, objects) go to people

  MaskScorer(const segmentation::DepthThresholdSegmenter& segmenter, double fy,
             FailureDumper& dumper, std::ostream* cases)
      : segmenter_(segmenter), fy_(fy), dumper_(dumper), cases_(cases) {}

  /// Frame `index`'s masks, one per detection of `d`; `trackDepth`: the depth of the track
  /// that took each detection (--pipeline; else none).
  void scoreFrame(size_t index, const sim::SimFrame& f, const FrameDetections& d,
                  const std::vector<core::ObjectMask>& masks,
                  const std::vector<double>* trackDepth) {
    const Eigen::Isometry3d T_camera_world = f.T_world_camera.inverse();
    for (size_t k = 0; k < masks.size(); ++k) {
      if (!d.truths[k]) continue;  // a detection on no true object (--boxes yolox)
      const auto& o = *d.truths[k];
      if (o.category != "person" && o.category != "car") continue;
      score(index, f, d.detections, k, o, masks[k], T_camera_world,
            trackDepth ? (*trackDepth)[k] : 0.0);
    }
  }

 private:
  void score(size_t index, const sim::SimFrame& f, const std::vector<core::Detection>& detections,
             size_t k, const sim::ObjectTruth& o, const core::ObjectMask& m,
             const Eigen::Isometry3d& T_camera_world, double trackDepth) {
    const bool person = o.category != "car";
    Scores& sc = person ? people : cars;
    ++sc.seen;
    // The person's true depth; none when all its visible pixels lie beyond the sensor's range
    // (no mask can hold them: such people are counted apart and not scored).
    const double z = segmentation::visibleMedianDepth(f.image.depth, f.image.label, o.id);
    if (z <= 0) {
      ++sc.outOfRange;
      return;
    }
    if (!m.valid) ++sc.invalid;
    const Occlusion c = o.visible_fraction >= 0.9   ? None
                        : o.visible_fraction >= 0.5 ? Mild
                                                    : Severe;
    const double iou = c != Severe ? scoreMask(f, detections[k], k, o, m, sc) : -1;
    if (!m.valid) return;
    const double torsoZ = (T_camera_world * o.T_world_object).translation().z();
    const double err = 100 * std::abs(m.d_t - z) / z;
    if (iou >= 0 && err <= 5) sc.iouRightDepth.push_back(iou);
    sc.depthErr[c].push_back(err);
    const double e = segmenter_.marginFor(detections[k]);
    sc.behind[c] += m.d_t > z + e;
    sc.inFront[c] += m.d_t < z - e;
    sc.torsoErr[c].push_back(100 * std::abs(m.d_t - torsoZ) / torsoZ);
    if (person) dumper_.consider(f, o, m, iou, err);
    if (cases_ && person)
      writeCase(*cases_, dumper_.prefix(), index, o, z, m, err, f, detections, trackDepth);
  }

  /// The mask's IoU, precision and recall, the IoU of its box alone, and where its pixels went.
  double scoreMask(const sim::SimFrame& f, const core::Detection& detection, size_t k,
                   const sim::ObjectTruth& o, const core::ObjectMask& m, Scores& sc) const {
    const cv::Mat truth = f.image.label == o.id;
    const double iou = segmentation::maskIoU(m, truth);
    sc.iou.push_back(iou);
    const int area = m.valid ? cv::countNonZero(m.mask) : 0;
    const int hit = m.valid ? cv::countNonZero(m.mask & truth(m.roi)) : 0;
    sc.precision.push_back(area ? double(hit) / area : 0);
    sc.recall.push_back(double(hit) / o.visible_pixels);
    sc.boxIoU.push_back(double(o.visible_pixels) / std::max(1, m.roi.area()));
    sc.iouAlone.push_back(
        segmentation::maskIoU(segmenter_.segmentOne(f.image.depth, detection, k, 0, fy_), truth));
    tallyPixels(f.image.label, f.image.depth, uint16_t(o.id), m, sc);
    return iou;
  }

  const segmentation::DepthThresholdSegmenter& segmenter_;
  double fy_;
  FailureDumper& dumper_;
  std::ostream* cases_;
};

void benchmark(const std::string& ini, const std::vector<std::string>& overrides,
               const segmentation::DepthThresholdSegmenter& segmenter, size_t every,
               BoxSource& boxes, FailureDumper& dumper,
               const std::optional<core::IniConfig>& pipeline, std::ostream* cases) {
  sim::ScenarioOptions options;
  options.load(core::IniConfig::fromFile(ini, overrides));
  const std::unique_ptr<sim::Sequence> sequence = sim::makeSequence(options);
  dumper.setPrefix(std::filesystem::path(ini).stem().string());
  MaskScorer scorer(segmenter, sequence->camera().fy, dumper, cases);
  Scores& s = scorer.people;
  sim::SimFrame f;
  std::optional<PerceptionStages> stages;
  if (pipeline) stages.emplace(*pipeline);
  // The tracker must see every frame; only every `every`-th is scored.
  const size_t step = stages ? 1 : every;
  for (size_t i = 0; i < sequence->frameCount(); i += step) {
    sequence->renderFrame(i, f);
    const FrameDetections d = boxes.of(f, sequence->camera());
    const auto t0 = std::chrono::steady_clock::now();
    const auto masks =
        stages ? stages->masks(f, d.detections, sequence->camera())
               : segmenter.segment(f.image.depth, d.detections, {}, sequence->camera().fy);
    if (i % every != 0) continue;
    s.ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    s.objects.push_back(d.detections.size());
    scorer.scoreFrame(i, f, d, masks, stages ? &stages->trackDepth() : nullptr);
  }
  std::printf("%s (%dx%d): %zu of %zu frames (every %zu), %s boxes of objects >= %.2f visible%s\n",
              ini.c_str(), sequence->camera().width, sequence->camera().height, s.ms.size(),
              sequence->frameCount(), every, boxes.mode().c_str(), boxes.minVisible(),
              stages ? ("; masks after " + stages->names() + " (--pipeline)").c_str() : "");
  if (boxes.mode() == "yolox")
    std::printf(
        "YOLOX-nano (input 416) boxed %zu of %zu people at least 0.5 visible (IoU >= 0.5 "
        "with the amodal box); only those are scored\n",
        boxes.halfVisibleFound, boxes.halfVisiblePeople);
  printTable(s, stages.has_value());
  std::vector<double> halfVisibleErr = s.depthErr[None];
  halfVisibleErr.insert(halfVisibleErr.end(), s.depthErr[Mild].begin(), s.depthErr[Mild].end());
  std::printf(
      "  summary, people >= 50 %% visible: mean mask IoU %.3f (%zu), mean d_t error %.2f %% "
      "(%zu)\n",
      mean(s.iou), s.iou.size(), mean(halfVisibleErr), halfVisibleErr.size());
  if (scorer.cars.seen > 0) printCars(scorer.cars);
  std::printf("\n");
}

/// The segmenter's settings as a pipeline reads [Segmentation], from --pipeline INI or
/// --seg-config INI (a system's [Segmentation] alone: each frame is still segmented alone, and
/// a bench of a system's masks needs no copy of its keys), else the method as method.md states
/// it (methodParams(); the stage's defaults are the shipped configuration); --seg-set then
/// overrides in any section. `pipeline`: the --pipeline ini.
struct SegmentationSetup {
  segmentation::DepthThresholdParams params;
  std::optional<core::IniConfig> pipeline;
};

SegmentationSetup segmentationSetup(const core::CommandLine& cl) {
  const std::string pipelineIni = cl.valueOr("--pipeline", "");
  const std::string segConfig = cl.valueOr("--seg-config", "");
  if (!pipelineIni.empty() && !segConfig.empty())
    throw core::UsageError(
        "--pipeline and --seg-config: give one (--pipeline reads [Segmentation] too)");
  const std::string iniFile = pipelineIni.empty() ? segConfig : pipelineIni;
  auto segIni = iniFile.empty() ? core::IniConfig::fromText("", "--seg-set")
                                : core::IniConfig::fromFile(iniFile, cl.all("--seg-set"));
  if (iniFile.empty())
    for (const auto& a : cl.all("--seg-set")) segIni.applyOverride(a);
  segmentation::SegmentationOptions options;
  if (iniFile.empty()) options.params = segmentation::methodParams();
  core::loadOptionsStrict(options, segIni, "Segmentation");
  SegmentationSetup setup{options.params, std::nullopt};
  if (!pipelineIni.empty()) setup.pipeline = segIni;
  return setup;
}

const char* const kUsage =
    R"(usage: bench-segmentation [--config params/sim/NAME.ini]... [--every N] [--set S.k=v]...
                          [--seg-set Segmentation.key=value]...
                          [--boxes amodal|visible|yolox [--model FILE.onnx]] [--min-visible F] [--dump DIR] [--dump-max N]
                          [--pipeline INI | --seg-config INI] [--cases FILE.csv]
       bench-segmentation -h | --help

Scores the depth-threshold segmentation (method.md section 1) against the simulator's ground
truth, with the ground-truth boxes as detections: mask IoU, precision and recall of people by
visibility, the error of the object depth d_t against the true depth (median depth of the
person's visible pixels) under mild and severe occlusion, and the segmentation time per frame;
cars apart. Run from the source tree (the default scenario is a relative path).

Options:
  --config FILE.ini      a scenario rendered in-process (repeatable; default
                         params/sim/indoor_people_high.ini; an augment scene scores the
                         inserted movers)
  --every N              score one frame in N (default 3)
  --set S.k=v            override a scenario key (repeatable)
  --seg-set S.k=v        override a segmentation key, e.g. Segmentation.e_person=0.4
                         (repeatable; over the --pipeline or --seg-config ini)
  --boxes amodal|visible|yolox
                         the detections' boxes: the simulator's amodal box (default), the
                         box round the visible pixels, or YOLOX-nano's on the rendered colour
                         (each scored against the true object it overlaps at IoU >= 0.5; the
                         people it misses are counted, not scored)
  --model FILE.onnx      YOLOX-nano for --boxes yolox (default ../shared/models/yolox_nano.onnx)
  --min-visible F        objects less visible than F get no box (default 0.2: the share below
                         which the system's GroundTruthDetector reports nothing)
  --dump DIR             write the worst masks as PNGs (green: right, red: not the person,
                         blue: missed)
  --dump-max N           masks --dump writes at most (default 12)
  --pipeline INI         score the masks the system ends a frame with: INI's [Segmentation],
                         then [Tracking] every frame, then [Retrack] (boxes =
                         tracked_detections), as dynslam runs them; the time is that of all
                         three
  --seg-config INI       take INI's [Segmentation] only (each frame alone)
  --cases FILE.csv       one row per scored person: scenario, frame, id, visible, true_depth,
                         d_t, d_alt, d_o, d_b, err_pct and the other overlapping object whose
                         visible depth is nearest d_t (id, depth, visible, detected),
                         track_depth
  -h, --help             print this text and exit

Exit codes: 0 done, 1 a bad scenario or ini, an output that cannot be written, 2 usage.
)";

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-segmentation", [&] {
    core::CommandLine cl({"--every", "--boxes", "--min-visible", "--dump", "--dump-max",
                          "--pipeline", "--seg-config", "--cases", "--model"},
                         {}, {"--config", "--set", "--seg-set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    std::vector<std::string> inis = cl.all("--config");
    if (inis.empty()) inis = {"params/sim/indoor_people_high.ini"};
    const SegmentationSetup setup = segmentationSetup(cl);
    const segmentation::DepthThresholdSegmenter segmenter(setup.params);
    const auto every =
        static_cast<size_t>(std::max(1LL, cl.optionalInteger("--every").value_or(3)));
    BoxSource boxes(cl.valueOr("--boxes", "amodal"),
                    cl.optionalDouble("--min-visible")
                        .value_or(detection::GroundTruthDetectorSettings{}.min_visible_fraction),
                    cl.valueOr("--model", "../shared/models/yolox_nano.onnx"));
    FailureDumper dumper(cl.valueOr("--dump", ""),
                         static_cast<size_t>(cl.optionalInteger("--dump-max").value_or(12)));
    std::ofstream cases;
    if (const auto path = cl.valueOr("--cases", ""); !path.empty()) {
      cases.open(path);
      if (!cases) throw std::runtime_error("--cases " + path + ": cannot write");
      cases << "scenario,frame,id,visible,true_depth,d_t,d_alt,d_o,d_b,err_pct,nearest_other_id,"
               "nearest_other_depth,nearest_other_visible,nearest_other_detected,track_depth\n";
    }
    for (const auto& ini : inis)
      benchmark(ini, cl.all("--set"), segmenter, every, boxes, dumper, setup.pipeline,
                cases.is_open() ? &cases : nullptr);
    dumper.write();
    return 0;
  });
}
