// Tracking quality and speed (issue 4): the Kalman depth-IoU tracker on the simulator's
// indoor_people_high scenario, scored with CLEAR-MOT and IDF1; optionally the same tracker on a
// real video through YOLOX-nano (tracking_video.cpp).
//
// Usage and flags: kUsage below (bench-tracking --help).
//
// The simulated run: the scenario rendered in-process twice (the first pass writes the
// ground truth to objects.txt in a temporary folder, which GroundTruthDetector reads as it would
// read dynslam-sim's; the second renders the images again for the segmentation), detections from
// GroundTruthDetector, object depth from DepthThresholdSegmenter (or the true depth: the median
// depth of the person's visible pixels; or the tracker's box-median fallback), then the tracker
// on the cached observations, once with the settings given (kBenchStart and --set) and once per
// swept value. Scoring rules (MotMetrics.h for the metrics):
// - truth: every object in view; "counted" when at least --min-visible of it is visible (what
//   the detector reports), else "don't care" (a hidden person cannot be demanded);
// - hypotheses: confirmed tracks matched this frame or coasting for at most --report-coasting
//   detector frames (DeepSORT reports tracks missed for at most 1), boxes clipped to the image
//   as the truth's are.
#include "tracking_diagnostics.h"
#include "tracking_run_set.h"
#include "tracking_sim_input.h"
#include "tracking_video.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/evaluation/MotMetrics.h>
#include <dynslam/tracking/Appearance.h>
#include <dynslam/tracking/KalmanBoxTracker.h>
#include <dynslam/tracking/TrackingStage.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>
#include <tuple>

namespace {

using namespace dynslam;
using bench::BenchSettings;
using bench::CachedRun;
using bench::percentile;
using bench::printIdentities;

struct TrackerRun {
  evaluation::MotResult mot;
  std::vector<double> ms;  // tracker time per frame
  int tracks_started = 0;
  double objects_per_frame = 0;
  std::vector<evaluation::MotFrame> frames;  // what was scored
  /// Per TrackMatch: observations taken that way, and of those the ones of another person than
  /// the track's id took last (a switch).
  std::map<tracking::TrackMatch, std::pair<int, int>> takenBy;
  std::vector<std::string> switchEvents;  // "frame 101: #5 t3 -> t4 (depth IoU)"
};

const char* matchName(tracking::TrackMatch m) {
  switch (m) {
    case tracking::TrackMatch::Overlap:
      return "depth IoU";
    case tracking::TrackMatch::CoastingOverlap:
      return "coasting IoU";
    case tracking::TrackMatch::Appearance:
      return "appearance";
    case tracking::TrackMatch::Started:
      return "new track";
    case tracking::TrackMatch::Revived:
      return "revival";
    case tracking::TrackMatch::Swapped:
      return "id swap";
    case tracking::TrackMatch::Repaired:
      return "id repair";
    case tracking::TrackMatch::None:
      break;
  }
  return "none";
}

/// |d - d_true| / d_true of every observation of a true object.
std::vector<double> depthErrors(const CachedRun& run) {
  std::vector<double> errors;
  for (const auto& f : run.frames)
    for (size_t k = 0; k < f.observations.size(); ++k) {
      const double truthDepth = f.observation_truth[k].depth;
      if (truthDepth > 0)
        errors.push_back(std::abs(f.observations[k].depth - truthDepth) / truthDepth);
    }
  return errors;
}

/// --trace: frame i's observations (truth id, box centre and size, d, d_alt, true depth) and the
/// tracks after the update (id, state, misses, the truth id of the observation taken, box centre
/// and size, filter depth).
void printTrace(size_t i, const bench::CachedFrame& f, const std::vector<core::Track>& tracks,
                const std::vector<tracking::TrackMatch>& matches) {
  std::printf("frame %zu  obs:", i);
  for (size_t k = 0; k < f.observations.size(); ++k) {
    const auto& o = f.observations[k];
    const auto& truth = f.observation_truth[k];
    std::printf(" [%zu t%d x%.0f %.0fx%.0f d%.2f a%.2f true%.2f v%.2f]", k, truth.id,
                o.box.x + o.box.width / 2, o.box.width, o.box.height, o.depth, o.depth_alt,
                truth.depth, truth.visible);
  }
  std::printf("\n           tracks:");
  for (size_t k = 0; k < tracks.size(); ++k) {
    const core::Track& t = tracks[k];
    const char state = t.state == core::TrackState::Confirmed   ? 'C'
                       : t.state == core::TrackState::Tentative ? 'T'
                                                                : 'L';
    const std::string taken =
        t.detection >= 0 ? "t" + std::to_string(f.observation_truth[t.detection].id) : "-";
    std::printf(" [#%d %c%d %s(%s) x%.0f %.0fx%.0f d%.2f]", t.id, state, t.misses, taken.c_str(),
                matchName(matches[k]), t.box.x + t.box.width / 2, t.box.width, t.box.height,
                t.depth);
  }
  std::printf("\n");
}

/// Counts, per TrackMatch, the observations the tracks took on frame i and the switches among
/// them (a track taking another person than it took last, `lastTruthOf`: track id -> truth id).
void tallySwitches(int i, const bench::CachedFrame& f, const std::vector<core::Track>& tracks,
                   const std::vector<tracking::TrackMatch>& matches,
                   std::map<int, int>& lastTruthOf, TrackerRun& r) {
  for (size_t k = 0; k < tracks.size(); ++k) {
    if (tracks[k].detection < 0) continue;
    const int truth = f.observation_truth[tracks[k].detection].id;
    auto& [taken, switched] = r.takenBy[matches[k]];
    ++taken;
    const auto last = lastTruthOf.find(tracks[k].id);
    if (last != lastTruthOf.end() && truth >= 0 && last->second >= 0 && last->second != truth) {
      ++switched;
      r.switchEvents.push_back("frame " + std::to_string(i) + ": #" + std::to_string(tracks[k].id) +
                               " t" + std::to_string(last->second) + " -> t" +
                               std::to_string(truth) + " (" + matchName(matches[k]) + ")");
    }
    lastTruthOf[tracks[k].id] = truth;
  }
}

TrackerRun runTracker(const CachedRun& run, const tracking::KalmanBoxTrackerParams& params,
                      int reportCoasting, int traceFirst = -1, int traceLast = -1) {
  tracking::KalmanBoxTracker tracker(params);
  TrackerRun r;
  std::vector<evaluation::MotFrame> mot;
  size_t observations = 0;
  const cv::Rect2d image(0, 0, run.image.width, run.image.height);
  std::map<int, int> lastTruthOf;  // track id -> truth id of the last observation it took
  for (const auto& f : run.frames) {
    const auto t0 = std::chrono::steady_clock::now();
    tracker.predict(f.t);
    tracker.update(f.observations, run.image);
    const std::vector<core::Track> tracks = tracker.tracks();
    r.ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    observations += f.observations.size();
    const int i = int(mot.size());
    const std::vector<tracking::TrackMatch> matches = tracker.matches();
    if (i >= traceFirst && i <= traceLast) printTrace(size_t(i), f, tracks, matches);
    tallySwitches(i, f, tracks, matches, lastTruthOf, r);
    evaluation::MotFrame m;
    m.truth = f.truth;
    for (const auto& t : tracks)
      if (t.state == core::TrackState::Confirmed && t.misses <= reportCoasting) {
        const cv::Rect2d box = cv::Rect2d(t.box.x, t.box.y, t.box.width, t.box.height) & image;
        if (!box.empty()) m.hypotheses.push_back({t.id, box});
      }
    mot.push_back(std::move(m));
  }
  r.mot = evaluation::evaluateMot(mot);
  r.frames = std::move(mot);
  r.tracks_started = tracker.tracksStarted();
  r.objects_per_frame = run.frames.empty() ? 0 : double(observations) / run.frames.size();
  return r;
}

/// The tracker the bench starts from, before --set: the method's association (method.md section
/// 2: rho_min 0.7, min_hits 3, no appearance, no gates) with reset_at_border, the tracker's
/// defaults every bench-tracking figure up to 2026-11-28 was measured from. The shipped
/// departures (the defaults now) come with --set, as docs/benchmarks.md's command gives them.
constexpr const char* kBenchStart =
    "[Tracking]\nrho_min = 0.7\nmin_hits = 3\nreid_max_distance = 0\nreid_memory = 0\n"
    "alternative_depth = false\ndepth_gate = 0\ninnovation_gate = 0\nreset_at_border = true\n";

tracking::KalmanBoxTrackerParams trackerParams(const BenchSettings& s,
                                               const std::vector<std::string>& overrides) {
  auto ini = s.system_ini.empty() ? core::IniConfig::fromText(kBenchStart, "bench-tracking --set")
                                  : core::IniConfig::fromFile(s.system_ini, {});
  for (const auto& o : overrides) ini.applyOverride(o);
  tracking::TrackingStage stage;  // validates the keys and values as the pipeline would
  stage.configure(ini, "Tracking");
  return stage.options().tracker;
}

/// One swept setting: a key and one of its values.
struct SweptValue {
  std::string key, value;
  /// "key=value" without the "Tracking." prefix, as the printouts name the setting.
  std::string label() const { return key.substr(9) + "=" + value; }
};

/// --sweep "Tracking.key=v1,v2,...[;Tracking.key2=a,b]": each key's values, one key at a time
/// (everything else as given; dynslam-sweep's --grid syntax, but no combinations). Empty: none.
std::vector<SweptValue> sweepValues(const BenchSettings& s) {
  std::vector<SweptValue> out;
  std::stringstream groups(s.sweep);
  for (std::string group; std::getline(groups, group, ';');) {
    if (group.empty()) continue;
    const size_t eq = group.find('=');
    if (eq == std::string::npos || group.rfind("Tracking.", 0) != 0 || eq + 1 == group.size())
      throw core::UsageError("--sweep must read Tracking.key=v1,v2,...[;Tracking.key2=...], not '" +
                             s.sweep + "'");
    std::stringstream items(group.substr(eq + 1));
    for (std::string v; std::getline(items, v, ',');) out.push_back({group.substr(0, eq), v});
  }
  return out;
}

/// The tracker's settings with one swept key set to v (everything else as given).
tracking::KalmanBoxTrackerParams sweptParams(const BenchSettings& s, const std::string& key,
                                             const std::string& v) {
  std::vector<std::string> overrides = s.tracker_overrides;
  overrides.push_back(key + "=" + v);
  return trackerParams(s, overrides);
}

/// The input's lines: scenario, detections and their depth, the gaps in the truth a tracker has
/// to bridge, and how far the truth moves between frames against rho_min.
void printInput(const BenchSettings& s, const CachedRun& run,
                const tracking::KalmanBoxTrackerParams& params) {
  const std::vector<double> depthError = depthErrors(run);
  std::printf("scenario        %s, %zu frames %dx%d, %zu people\n", s.config.c_str(),
              run.frames.size(), run.image.width, run.image.height, run.people);
  char detector[160];
  if (s.detector == "yolox")
    std::snprintf(detector, sizeof detector, "YOLOX-nano (input 416, %s)", s.model.c_str());
  else
    std::snprintf(detector, sizeof detector,
                  "GroundTruthDetector: miss rate %.2f, jitter %.1f px, reported when >= %.2f "
                  "visible",
                  s.miss_rate, s.jitter, s.min_visible);
  std::printf(
      "detections      %s; depth: %s (median error %.1f %%, %.1f %% of detections off by "
      "more than 15 %%)\n",
      detector, depthSource(s).c_str(), 100 * percentile(depthError, 0.5),
      100.0 *
          double(std::count_if(depthError.begin(), depthError.end(),
                               [](double e) { return e > 0.15; })) /
          double(std::max<size_t>(1, depthError.size())));
  printTruthGaps(run);
  const double below = double(std::count_if(run.selfRho.begin(), run.selfRho.end(),
                                            [&](double r) { return r <= params.rho_min; }));
  std::printf(
      "truth motion    depth IoU of a visible object's true box with its own box one "
      "frame before: median %.3f, p10 %.3f, p1 %.3f; %.1f %% <= rho_min\n",
      percentile(run.selfRho, 0.5), percentile(run.selfRho, 0.1), percentile(run.selfRho, 0.01),
      100 * below / std::max<size_t>(1, run.selfRho.size()));
}

/// The tracker's settings and scores on the run, and its time per frame.
void printScores(const BenchSettings& s, const tracking::KalmanBoxTrackerParams& params,
                 const TrackerRun& main, double prepSeconds) {
  const auto& m = main.mot;
  std::printf(
      "tracker         rho_min %.2f (coasting tracks: %.2f), max_age %d, min_hits %d, "
      "innovation_gate %.1f, depth_gate %.2f; reported: confirmed tracks coasting <= %d frames\n",
      params.rho_min, std::min(params.rho_min, params.rho_min_coasting), params.max_age,
      params.min_hits, params.innovation_gate, params.depth_gate, s.report_coasting);
  std::printf("ground truth    %zu boxes counted, %zu truth ids; %zu tracks started\n",
              m.truth_boxes, m.truth_ids, size_t(main.tracks_started));
  std::printf("MOTA            %.3f (target >= 0.90; ratio %.2f)  [FN %zu, FP %zu, IDsw %zu]\n",
              m.mota, m.mota / 0.90, m.misses, m.false_positives, m.id_switches);
  std::printf("IDF1            %.3f (target >= 0.90; ratio %.2f)  [IDP %.3f, IDR %.3f]\n", m.idf1,
              m.idf1 / 0.90, m.idp, m.idr);
  std::printf("ID switches     %zu; fragmentations %zu; MOTP (mean IoU) %.3f\n", m.id_switches,
              m.fragmentations, m.motp);
  const double med = percentile(main.ms, 0.5);
  std::printf(
      "tracker time    median %.4f ms per frame, p90 %.4f ms, %.1f detections per frame "
      "(target <= 0.2 ms; ratio %.3f)\n",
      med, percentile(main.ms, 0.9), main.objects_per_frame, med / 0.2);
  std::printf("(render, detect and segment: %.1f s)\n", prepSeconds);
}

/// --identities: the tracks that covered each person, and the switches by round.
void printIdentityReport(const TrackerRun& main) {
  printIdentities(main.frames);
  std::printf("\nswitches by round (a track taking another person than it took last):\n");
  for (const auto& [match, counts] : main.takenBy)
    std::printf("  %-13s %6d observations taken, %4d switches\n", matchName(match), counts.first,
                counts.second);
  for (const auto& e : main.switchEvents) std::printf("  %s\n", e.c_str());
}

/// --sweep: each swept value's scores on the same run.
void printSweep(const BenchSettings& s, const CachedRun& run) {
  const std::vector<SweptValue> swept = sweepValues(s);
  if (swept.empty()) return;
  std::printf("\nsweep (one key at a time, everything else as above)\n");
  std::printf("  %28s   MOTA   IDF1  IDsw  frag    FP    FN  tracks\n", "setting");
  for (const SweptValue& v : swept) {
    const TrackerRun r = runTracker(run, sweptParams(s, v.key, v.value), s.report_coasting);
    std::printf("  %28s  %5.3f  %5.3f  %4zu  %4zu  %4zu  %4zu  %6d\n", v.label().c_str(),
                r.mot.mota, r.mot.idf1, r.mot.id_switches, r.mot.fragmentations,
                r.mot.false_positives, r.mot.misses, r.tracks_started);
  }
}

void benchSimulation(const BenchSettings& s) {
  const tracking::KalmanBoxTrackerParams params = trackerParams(s, s.tracker_overrides);
  const auto start = std::chrono::steady_clock::now();
  const CachedRun run = prepareSimulatedRun(s);
  const double prepSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const TrackerRun main = runTracker(run, params, s.report_coasting, s.trace_first, s.trace_last);
  printInput(s, run, params);
  printScores(s, params, main, prepSeconds);
  printAppearanceSeparation(run);
  if (s.identities) printIdentityReport(main);
  printSweep(s, run);
}

/// --scenarios / --seeds: the settings given and each sweep value over every run of the set.
void benchSimulationSet(const BenchSettings& s, const std::vector<int>& scenarios,
                        const std::vector<int>& seeds, int jobs) {
  std::vector<tracking::KalmanBoxTrackerParams> params = {trackerParams(s, s.tracker_overrides)};
  std::vector<std::string> names = {"as given"};
  for (const SweptValue& v : sweepValues(s)) {
    params.push_back(sweptParams(s, v.key, v.value));
    names.push_back(v.label());
  }
  bench::benchRunSet(s, scenarios, seeds, jobs, names, [&](const CachedRun& run) {
    std::vector<bench::RunScore> scores;
    for (const auto& p : params) {
      const evaluation::MotResult m = runTracker(run, p, s.report_coasting).mot;
      scores.push_back({m.mota, m.idf1, m.id_switches});
    }
    return scores;
  });
}

/// The single run's and the run set's settings from the command line.
BenchSettings parseSettings(const core::CommandLine& cl) {
  BenchSettings s;
  s.config = cl.valueOr("--config", s.config);
  s.frames = size_t(cl.optionalInteger("--frames").value_or(0));
  s.miss_rate = cl.optionalDouble("--miss-rate").value_or(s.miss_rate);
  s.jitter = cl.optionalDouble("--jitter").value_or(s.jitter);
  s.min_visible = cl.optionalDouble("--min-visible").value_or(s.min_visible);
  s.seed = uint32_t(cl.optionalInteger("--seed").value_or(s.seed));
  s.detector = cl.valueOr("--detector", s.detector);
  if (s.detector != "truth" && s.detector != "yolox")
    throw core::UsageError("--detector must be truth or yolox, not '" + s.detector + "'");
  if (s.detector == "yolox" && (cl.has("--miss-rate") || cl.has("--jitter")))
    throw core::UsageError("--miss-rate and --jitter shape the truth detector; not with yolox");
  s.model = cl.valueOr("--model", s.model);
  s.system_ini = cl.valueOr("--system", "");
  s.depth = cl.valueOr("--depth", s.depth);
  if (s.depth != "segmentation" && s.depth != "truth" && s.depth != "box")
    throw core::UsageError("--depth must be segmentation, truth or box, not '" + s.depth + "'");
  s.true_depth_below = cl.optionalDouble("--true-depth-below").value_or(0.0);
  if (s.true_depth_below < 0 || s.true_depth_below > 1 ||
      (s.true_depth_below > 0 && s.depth != "segmentation"))
    throw core::UsageError(
        "--true-depth-below must lie in [0, 1] and goes with --depth segmentation");
  s.report_coasting = int(cl.optionalInteger("--report-coasting").value_or(s.report_coasting));
  s.sweep = cl.valueOr("--sweep", s.sweep);
  s.identities = cl.has("--identities");
  if (cl.has("--trace")) {
    const std::string range = cl.required("--trace");
    if (std::sscanf(range.c_str(), "%d-%d", &s.trace_first, &s.trace_last) != 2 ||
        s.trace_first < 0 || s.trace_last < s.trace_first)
      throw core::UsageError("--trace must read FIRST-LAST (frame numbers), not '" + range + "'");
  }
  for (const auto& o : cl.all("--set"))
    (o.rfind("Tracking.", 0) == 0       ? s.tracker_overrides
     : o.rfind("Segmentation.", 0) == 0 ? s.segmentation_overrides
                                        : s.sim_overrides)
        .push_back(o);
  return s;
}

/// --video: the tracker with the --set settings on a real video.
void runVideo(const core::CommandLine& cl, const BenchSettings& s) {
  VideoBenchSettings v;
  v.video = cl.required("--video");
  v.model = cl.required("--model");
  v.strip = cl.required("--strip");
  v.frames = size_t(cl.optionalInteger("--video-frames").value_or(0));
  v.tracker = trackerParams(s, s.tracker_overrides);
  benchVideo(v);
}

/// --scenarios / --seeds: a set of runs.
void runSet(const core::CommandLine& cl, const BenchSettings& s) {
  if (cl.has("--seed") || cl.has("--trace") || s.identities)
    throw core::UsageError(
        "--scenarios / --seeds run a set: give --seeds instead of --seed, and --trace or "
        "--identities to single runs only");
  const std::vector<int> scenarios =
      cl.has("--scenarios") ? bench::parseRange("--scenarios", cl.required("--scenarios"))
                            : std::vector<int>{1};
  const std::vector<int> seeds = cl.has("--seeds")
                                     ? bench::parseRange("--seeds", cl.required("--seeds"))
                                     : std::vector<int>{int(s.seed)};
  const long long hardware = std::max(1u, std::thread::hardware_concurrency());
  const long long jobs = cl.optionalInteger("--jobs").value_or(hardware);
  if (jobs < 1) throw core::UsageError("--jobs must be at least 1");
  benchSimulationSet(s, scenarios, seeds, int(jobs));
}

const char* const kUsage =
    R"(usage: bench-tracking [--config FILE.ini] [--frames N] [--miss-rate P] [--jitter PX]
                      [--min-visible F] [--seed N] [--detector truth|yolox [--model FILE]]
                      [--depth segmentation|truth|box] [--true-depth-below V] [--report-coasting N]
                      [--system INI]
                      [--sweep "Tracking.key=v1,v2[;Tracking.key2=a,b]" | --sweep '']
                      [--set Section.key=value]... [--identities] [--trace FIRST-LAST]
       bench-tracking --scenarios A-B [--seeds A-B] [--jobs N] [options above]
       bench-tracking --video FILE --model FILE.onnx --strip FILE.png [--video-frames N]
       bench-tracking -h | --help

The Kalman depth-IoU tracker (method.md section 2) on a simulated scenario, scored with
CLEAR-MOT and IDF1 (MOTA, MOTP, ID switches, fragmentations, IDF1/IDP/IDR), once with the
ini's settings and once per swept value: detections from the ground-truth detector (with
misses and jitter) or from YOLOX-nano on the rendered colour, object depth from the depth segmentation (or the truth). With --video, the
same tracker on a real video through YOLOX-nano. Run from the source tree (the default
scenario is a relative path).

Options:
  --config FILE.ini      the scenario (default params/sim/indoor_people_high.ini)
  --frames N             frames scored (default: all)
  --miss-rate P          share of detections the detector drops at random (default 0.1)
  --jitter PX            pixels of random jitter on the detected boxes (default 3)
  --min-visible F        objects less visible than F are "don't care" truth and get no
                         detection (default 0.2)
  --seed N               the detector's seed (default 1)
  --detector truth|yolox the ground-truth detector (default) or YOLOX-nano (--model) on the
                         rendered colour (works on augment scenes: real frames, inserted people)
  --depth segmentation|truth|box
                         the object depth the tracker gets: the segmentation's (default),
                         the true depth, or the tracker's box-median fallback
  --true-depth-below V   with --depth segmentation: a person less than V visible gets the true
                         depth instead (default 0: off)
  --system INI           start from INI's [Tracking] and [Segmentation] (unset keys: the
                         shipped defaults) instead of the method-like start the figures in
                         docs/benchmarks.md use; --set then overrides
  --report-coasting N    report a confirmed track coasting for at most N detector frames
                         (default 1, as DeepSORT)
  --sweep TEXT           tracker keys swept one at a time, "Tracking.key=v1,v2;..." (default
                         Tracking.rho_min=0.3,0.5,0.6,0.7,0.8; '' for none)
  --set Section.key=value
                         override a key (repeatable): Tracking.* goes to the tracker,
                         Segmentation.* to the segmentation, the rest to the scenario
  --identities           print which tracks covered each true identity
  --trace FIRST-LAST     print the tracker's frames FIRST..LAST
  --scenarios A-B        a set of runs: these Scenario.seed values (choreographies; "2-13",
                         "1,4,7" or "5"), each with every detector seed of --seeds; prints one
                         row per run and per configuration the means
  --seeds A-B            the detector seeds of a set (default: --seed's)
  --jobs N               runs of a set at once (default: one per core)
  --video FILE           the tracker on a real video instead (needs --model and --strip)
  --model FILE.onnx      YOLOX-nano for --video and --detector yolox (default
                         ../shared/models/yolox_nano.onnx with --detector yolox)
  --strip FILE.png       write four annotated frames of the video side by side
  --video-frames N       frames of the video (default: all)
  -h, --help             print this text and exit

Exit codes: 0 done, 1 a bad scenario, model or video, 2 usage.
)";

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-tracking", [&] {
    core::CommandLine cl({"--config",      "--frames",
                          "--miss-rate",   "--jitter",
                          "--min-visible", "--seed",
                          "--depth",       "--report-coasting",
                          "--video",       "--model",
                          "--strip",       "--video-frames",
                          "--sweep",       "--trace",
                          "--scenarios",   "--seeds",
                          "--jobs",        "--true-depth-below",
                          "--detector",    "--system"},
                         {"--identities"}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const BenchSettings s = parseSettings(cl);
    if (cl.has("--video"))
      runVideo(cl, s);
    else if (cl.has("--scenarios") || cl.has("--seeds"))
      runSet(cl, s);
    else
      benchSimulation(s);
    return 0;
  });
}
