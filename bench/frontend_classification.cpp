// Dynamic-feature classification and rigid point sets (issue 5, method.md sections 3-4), scored
// against the simulator's ground truth, plus the real static room of 7-Scenes.
//
//   build/bin/dynslam-sim --config params/sim/indoor_people_high.ini --out /tmp/sim/indoor
//   build/bin/bench-classification --sim /tmp/sim/indoor [--config params/sim_frontend.ini]
//       [--masks pipeline|truth] [--features stage|klt] [--max-frames N]
//       [--per-frame FILE.csv] [--set Section.key=value]...
//   build/bin/bench-classification --rawlog /tmp/7s/7scenes.rawlog --config
//   params/7scenes_frontend.ini
//
// The frames come from the rawlog through io's FrameReader (RawlogSource + SensorSync on a thread
// of their own), as in `dynslam`, and go through the stages of the ini's [pipeline] (created from
// the same registry as `dynslam`; with --sim, Detection.objects is set to DIR/objects.txt). --masks
// truth replaces, just before DynamicClassification, each mask of a detection that came from the
// ground truth with the object's true pixels (label == id inside the box): the classification
// scored without the segmentation's errors. --features klt uses a plain Shi-Tomasi/KLT stand-in
// (classification_klt_standin.h) instead of the FeatureTracking stage (the default when no such
// stage is registered). Scoring rules: classification_scoring.h. Timings: wall clock of each
// stage per frame, medians within the run.
#include "classification_klt_standin.h"
#include "classification_scoring.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/Median.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/frontend/DynamicClassificationStage.h>
#include <dynslam/io/FrameReader.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/system/BuiltinStages.h>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>

namespace {

using namespace dynslam;
namespace fs = std::filesystem;

struct Settings {
  std::string sim, rawlog, config = "params/sim_frontend.ini", masks = "pipeline", features;
  long max_frames = -1;
  std::string per_frame;  ///< --per-frame: one CSV row of counts per scored frame
  std::vector<std::string> overrides;
};

struct StageSlot {
  std::string name;
  std::unique_ptr<core::Stage> stage;  ///< null: the KLT stand-in
  std::vector<double> ms;
};

/// Masks of ground-truth detections replaced by the object's true pixels.
void useTrueMasks(core::Frame& frame, const cv::Mat& labels) {
  for (auto& m : frame.object_masks) {
    if (m.detection < 0 || size_t(m.detection) >= frame.detections.size()) continue;
    const int id = frame.detections[size_t(m.detection)].truth_id;
    if (id < 0 || m.roi.empty()) continue;
    m.mask = labels(m.roi) == id;
    m.valid = cv::countNonZero(m.mask) > 0;
  }
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * double(v.size())))];
}

void printRatio(const char* what, double value, double target, bool atLeast, const char* unit) {
  std::printf("%-44s %8.4g%s (target %s %g%s; ratio %.2f)%s\n", what, value, unit,
              atLeast ? ">=" : "<=", target, unit, target ? value / target : 0.0,
              (atLeast ? value >= target : value <= target) ? "" : "  MISSED");
}

/// The stages of the ini's [pipeline], configured; the KLT stand-in (a null stage) in place of
/// FeatureTracking when `standIn`.
std::vector<StageSlot> makeStages(const core::IniConfig& cfg, bool standIn) {
  core::StageRegistry registry;
  system::registerBuiltinStages(registry);
  std::vector<StageSlot> stages;
  for (const auto& e : core::pipelineStageEntries(cfg)) {
    StageSlot slot{e.entry, nullptr, {}};
    if (!(e.class_name == "FeatureTracking" && standIn)) {
      slot.stage = registry.create(e.class_name);
      slot.stage->configure(cfg, e.section);
    } else {
      slot.name = "FeatureTracking (KLT stand-in)";
    }
    stages.push_back(std::move(slot));
  }
  return stages;
}

/// The simulator's truth (--sim): objects.txt, the camera poses and each frame's labels.
struct SimTruth {
  std::string dir;
  core::ObjectGroundTruthIndex objects;
  core::Trajectory cameras;

  bench::Truth frame(size_t index) const {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.png", index);
    bench::Truth t;
    const std::string path = (fs::path(dir) / "labels" / name).string();
    t.labels = cv::imread(path, cv::IMREAD_UNCHANGED);
    if (t.labels.empty() || t.labels.type() != CV_16UC1)
      throw std::runtime_error("cannot read the 16-bit label image '" + path + "'");
    t.objects = objects.byFrame(index);
    if (index >= cameras.size())
      throw std::runtime_error("groundtruth.tum has no pose for frame " + std::to_string(index));
    t.T_world_camera = cameras[index].T_world_body;
    return t;
  }
};

/// What the run counts, frame by frame.
struct Tally {
  bench::ClassificationScore score;
  std::optional<bench::Truth> previous;
  std::map<std::int64_t, int> trackLength;
  std::vector<double> cameraRotErr, cameraTransErr;
  size_t frames = 0, features = 0, staticFeatures = 0, withDepth = 0;
  size_t objectFeatures = 0, staticObjectFeatures = 0;
  // --per-frame: where the static set is contaminated (features of moving objects taken for
  // Static feed the estimator in remove mode) and where moving is over-called.
  std::ofstream perFrame;

  /// The camera motion the classifier removed, against the ground truth.
  void addCameraMotion(const std::vector<StageSlot>& stages, const bench::Truth& truth) {
    for (const auto& slot : stages)
      if (const auto* dc =
              dynamic_cast<const frontend::DynamicClassificationStage*>(slot.stage.get());
          dc && previous && frames > 0) {
        const Eigen::Isometry3d gt = truth.T_world_camera.inverse() * previous->T_world_camera;
        const auto& e = dc->classifier()->lastCameraMotion();
        cameraRotErr.push_back(frontend::rotationAngleDeg(e.motion.R.transpose() * gt.linear()));
        cameraTransErr.push_back((e.motion.t - gt.translation()).norm());
      }
  }

  void addFeatures(const core::Frame& frame) {
    for (const auto& f : frame.features) {
      ++features;
      staticFeatures += f.feature_class == core::FeatureClass::Static;
      if (f.object_id >= 0) {
        ++objectFeatures;
        staticObjectFeatures += f.feature_class == core::FeatureClass::Static;
      }
      withDepth += f.depth > 0;
      trackLength[f.id] = std::max(trackLength[f.id], f.track_length);
    }
  }

  void addScore(const core::Frame& frame, bench::Truth truth) {
    const bool consecutive = previous && frames > 1;
    const bench::ClassificationScore before = score;
    score.add(frame, truth, consecutive ? &*previous : nullptr);
    if (perFrame.is_open())
      perFrame << frame.index << ',' << std::fixed << std::setprecision(6) << frame.t << ','
               << (score.tn + score.fn) - (before.tn + before.fn) << ',' << score.fn - before.fn
               << ',' << (score.tp + score.fp) - (before.tp + before.fp) << ','
               << score.fp - before.fp << '\n';
    previous = std::move(truth);
  }
};

/// One frame through the stages (timed), --masks truth applied before the classification.
void processFrame(core::Frame& frame, std::vector<StageSlot>& stages, bench::KltStandIn& klt,
                  const std::optional<bench::Truth>& truth, bool trueMasks) {
  for (auto& slot : stages) {
    if (truth && trueMasks && slot.name.rfind("DynamicClassification", 0) == 0)
      useTrueMasks(frame, truth->labels);
    const auto t0 = std::chrono::steady_clock::now();
    if (slot.stage)
      slot.stage->process(frame);
    else
      klt.process(frame);
    slot.ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
}

/// The dynamic class's scores and where its errors come from.
void printClassScores(const bench::ClassificationScore& score) {
  std::printf(
      "dynamic class  TP %zu  FP %zu (%zu background, %zu on non-moving objects)  FN %zu "
      "(%zu on no object, %zu on objects judged static)  TN %zu\n",
      score.tp, score.fp, score.fpBackground, score.fpNonMovingObject, score.fn, score.fnNoObject,
      score.fnJudgedStatic, score.tn);
  printRatio("dynamic-class precision", score.precision(), 0.95, true, "");
  printRatio("dynamic-class recall", score.recall(), 0.90, true, "");
  std::printf("%-44s precision %.4f, recall %.4f (TP %zu FP %zu FN %zu TN %zu)\n",
              "  features with depth only:", score.precisionWithDepth(), score.recallWithDepth(),
              score.tpDepth, score.fpDepth, score.fnDepth, score.tnDepth);
  for (const auto& [misses, title] :
       {std::pair{&score.depthMisses, "with"}, std::pair{&score.depthlessMisses, "without"}}) {
    if (misses->empty()) continue;
    std::printf("  false negatives %s depth, by object and place:\n", title);
    for (const auto& [cause, n] : *misses) std::printf("    %-60s %zu\n", cause.c_str(), n);
  }
  if (!score.falsePositives.empty()) {
    std::printf("%-44s\n", "  false positives, by what the pixel shows and whose feature:");
    for (const auto& [cause, n] : score.falsePositives)
      std::printf("    %-60s %zu\n", cause.c_str(), n);
  }
}

/// The objects' decisions: non-moving ones static, moving ones dynamic.
void printObjectScores(const bench::ClassificationScore& score) {
  for (const auto& [category, n] : score.nonMoving) {
    const std::string what = "non-moving " + category + ": frames classified static";
    printRatio(what.c_str(), n.first ? double(n.second) / n.first : 0, 0.90, true, "");
    std::printf("%-44s (%zu object-frames with >= 3 features)\n", "", n.first);
    std::string causes;
    if (const auto misses = score.nonMovingMisses.find(category);
        misses != score.nonMovingMisses.end())
      for (const auto& [cause, count] : misses->second)
        causes += (causes.empty() ? "" : ", ") + std::to_string(count) + " " + cause;
    std::printf("%-44s frames judged moving, by cause: %s\n", "",
                causes.empty() ? "none" : causes.c_str());
  }
  for (const auto& [category, n] : score.moving)
    std::printf("%-44s %8.4g (%zu object-frames)\n",
                ("moving " + category + ": frames classified dynamic").c_str(),
                n.first ? double(n.second) / n.first : 0, n.first);
}

/// The rigid sets' motion errors, the tracking errors and the background flow's length.
void printMotionScores(const bench::ClassificationScore& score) {
  const std::map<std::string, std::pair<double, double>> targets{{"person", {2.0, 0.02}},
                                                                 {"car", {0.5, 0.01}}};
  for (const auto& [category, errs] : score.rotErrDeg) {
    const auto target = targets.count(category) ? targets.at(category) : std::make_pair(2.0, 0.02);
    std::printf("rigid sets on moving %ss: %zu set-frames\n", category.c_str(), errs.size());
    printRatio(("  median rotation error, " + category).c_str(), dynslam::core::upperMedian(errs),
               target.first, false, " deg");
    printRatio(("  median translation error, " + category).c_str(),
               dynslam::core::upperMedian(score.transErrM.at(category)), target.second, false,
               " m");
  }
  std::printf("rigid sets not on a moving object: %zu\n", score.rigidSetsUnmatched);
  std::printf("feature tracking error against the true motions, features with depth (px):\n");
  for (const auto& [what, errs] : score.trackingErrorPx)
    std::printf("  %-22s median %5.2f  p90 %6.2f  (%zu tracks)\n", what.c_str(),
                dynslam::core::upperPercentile(errs, 0.5),
                dynslam::core::upperPercentile(errs, 0.9), errs.size());
  const auto& ratio = score.backgroundFlowRatio;
  std::printf(
      "background flow, tracked along the true one over the true one (median; flows "
      ">= 1 px): nearer than %.0f m %.5f (%zu), farther %.5f (%zu)\n",
      score.kNearFlowDepth, dynslam::core::upperMedian(ratio[0]), ratio[0].size(),
      dynslam::core::upperMedian(ratio[1]), ratio[1].size());
}

void printReport(const Settings& s, const std::string& rawlog, const Tally& t, bool standIn,
                 bool simulated, const std::vector<StageSlot>& stages) {
  double lengthSum = 0;
  for (const auto& [id, n] : t.trackLength) lengthSum += n;
  std::printf("input          %s, %zu frames, config %s, masks %s, features %s\n", rawlog.c_str(),
              t.frames, s.config.c_str(), s.masks.c_str(),
              standIn ? "KLT stand-in" : "FeatureTracking stage");
  std::printf(
      "features       %.1f per frame (%.1f %% with depth), %zu tracks, mean track length %.1f "
      "frames\n",
      t.frames ? double(t.features) / t.frames : 0,
      t.features ? 100.0 * t.withDepth / t.features : 0, t.trackLength.size(),
      t.trackLength.empty() ? 0 : lengthSum / t.trackLength.size());
  if (simulated) {
    std::printf("camera motion  median error %.3f deg, %.1f mm per frame (p90 %.3f deg, %.1f mm)\n",
                dynslam::core::upperMedian(t.cameraRotErr),
                1000 * dynslam::core::upperMedian(t.cameraTransErr),
                percentile(t.cameraRotErr, 0.9), 1000 * percentile(t.cameraTransErr, 0.9));
    printClassScores(t.score);
    printObjectScores(t.score);
    printMotionScores(t.score);
  } else {
    printRatio("features classified static", t.features ? double(t.staticFeatures) / t.features : 0,
               0.98, true, "");
    std::printf("%-44s %zu of %zu features on detected objects (%.1f %%), %.4f of them static\n",
                "  of which on objects:", t.objectFeatures, t.features,
                t.features ? 100.0 * t.objectFeatures / t.features : 0,
                t.objectFeatures ? double(t.staticObjectFeatures) / t.objectFeatures : 0);
  }
  for (const auto& slot : stages) {
    const double m = dynslam::core::upperMedian(slot.ms);
    if (slot.name.rfind("DynamicClassification", 0) == 0)
      printRatio("classification + rigid sets, median per frame", m, 1.0, false, " ms");
    else
      std::printf("%-44s %8.4g ms median per frame\n", slot.name.c_str(), m);
  }
}

void run(const Settings& s) {
  std::vector<std::string> overrides = s.overrides;
  std::string rawlog = s.rawlog;
  std::optional<SimTruth> sim;
  if (!s.sim.empty()) {
    rawlog = (fs::path(s.sim) / "sim.rawlog").string();
    const std::string objectsPath = (fs::path(s.sim) / "objects.txt").string();
    overrides.insert(overrides.begin(), "Detection.objects=" + objectsPath);
    sim.emplace(SimTruth{s.sim,
                         core::ObjectGroundTruthIndex(core::readObjectGroundTruth(objectsPath)),
                         core::readTum((fs::path(s.sim) / "groundtruth.tum").string())});
  }
  const auto cfg = core::IniConfig::fromFile(s.config, overrides);
  core::StageRegistry registry;
  system::registerBuiltinStages(registry);
  const bool standIn =
      s.features == "klt" || (s.features.empty() && !registry.contains("FeatureTracking"));
  std::vector<StageSlot> stages = makeStages(cfg, standIn);
  io::SensorSyncOptions syncOptions;
  core::loadOptionsStrict(syncOptions, cfg, io::SensorSync::kSection);
  io::FrameReader reader(rawlog, syncOptions);
  bench::KltStandIn klt;

  Tally t;
  if (!s.per_frame.empty()) {
    t.perFrame.open(s.per_frame, std::ios::trunc);
    t.perFrame << "frame,t_s,static,static_on_moving,dynamic,dynamic_on_still\n";
    if (!t.perFrame) throw std::runtime_error("cannot write --per-frame '" + s.per_frame + "'");
  }
  while (!(s.max_frames >= 0 && long(t.frames) >= s.max_frames)) {
    std::optional<core::Frame> next = reader.next();
    if (!next) break;
    core::Frame& frame = *next;
    std::optional<bench::Truth> truth;
    if (sim) truth = sim->frame(frame.index);
    processFrame(frame, stages, klt, truth, s.masks == "truth");
    if (truth) t.addCameraMotion(stages, *truth);
    ++t.frames;
    t.addFeatures(frame);
    if (truth) t.addScore(frame, std::move(*truth));
    if (t.frames % 500 == 0) std::fprintf(stderr, "  %zu frames\n", t.frames);
  }
  for (auto& slot : stages)
    if (slot.stage) slot.stage->finish();
  printReport(s, rawlog, t, standIn, sim.has_value(), stages);
}

const char* const kUsage =
    R"(usage: bench-classification --sim DIR [--config FILE.ini] [--masks pipeline|truth]
                            [--features stage|klt] [--max-frames N] [--per-frame FILE.csv]
                            [--set Section.key=value]...
       bench-classification --rawlog FILE.rawlog --config FILE.ini [--max-frames N]
                            [--set Section.key=value]...
       bench-classification -h | --help

Dynamic-feature classification and rigid point sets (method.md sections 3-4): the frames of a
rawlog go through the stages of the ini's [pipeline] as in dynslam; with --sim they are scored
against the simulator's ground truth (dynamic precision / recall, where the errors come from,
non-moving objects judged static, rigid-set motion errors), with --rawlog (a static scene such
as 7-Scenes) every feature judged dynamic is an error. Prints the scores and each stage's
median time per frame.

Options:
  --sim DIR              a dynslam-sim output folder (sim.rawlog, labels/, objects.txt,
                         groundtruth.tum); Detection.objects is set to DIR/objects.txt
  --rawlog FILE.rawlog   a real rawlog instead (give exactly one of --sim and --rawlog)
  --config FILE.ini      the system's ini (default params/sim_frontend.ini)
  --masks pipeline|truth
                         the masks classification sees: the pipeline's (default), or each
                         ground-truth detection's true pixels (the classification without the
                         segmentation's errors)
  --features stage|klt   the FeatureTracking stage (default when the ini has one) or a plain
                         Shi-Tomasi/KLT stand-in
  --max-frames N         frames at most (default: all)
  --per-frame FILE.csv   one row per scored frame: frame,t_s,static,static_on_moving,dynamic,
                         dynamic_on_still (feature counts: predicted static, of those on a
                         moving object; predicted dynamic, of those on a still one)
  --set Section.key=value
                         override an ini value (repeatable)
  -h, --help             print this text and exit

Exit codes: 0 done, 1 bad input or configuration, 2 usage.
)";

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-classification", [&] {
    core::CommandLine cl(
        {"--sim", "--rawlog", "--config", "--masks", "--features", "--max-frames", "--per-frame"},
        {}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    Settings s;
    s.sim = cl.valueOr("--sim", "");
    s.rawlog = cl.valueOr("--rawlog", "");
    if (s.sim.empty() == s.rawlog.empty())
      throw core::UsageError("give exactly one of --sim DIR and --rawlog FILE");
    s.config = cl.valueOr("--config", s.config);
    s.masks = cl.valueOr("--masks", s.masks);
    if (s.masks != "pipeline" && s.masks != "truth")
      throw core::UsageError("--masks must be pipeline or truth, not '" + s.masks + "'");
    s.features = cl.valueOr("--features", "");
    if (!s.features.empty() && s.features != "stage" && s.features != "klt")
      throw core::UsageError("--features must be stage or klt, not '" + s.features + "'");
    s.max_frames = long(cl.optionalInteger("--max-frames").value_or(-1));
    s.per_frame = cl.valueOr("--per-frame", "");
    s.overrides = cl.all("--set");
    run(s);
    return 0;
  });
}
