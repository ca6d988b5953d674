// Feature tracking (issue 5 item 1, method.md section 3): speed at 640x480 with 150 features
// and track quality, on a simulated sequence (scored against its ground truth) and on the real
// static room of 7-Scenes.
//
//   build/bin/dynslam-sim --config params/sim/indoor_people_high.ini --out /tmp/sim/indoor
//   build/bin/sevenscenes2rawlog --in ../shared/data/7scenes --out /tmp/7s/7scenes.rawlog
//   build/bin/bench-frontend --sim /tmp/sim/indoor --rawlog /tmp/7s/7scenes.rawlog
//       [--max-frames N] [--set FeatureTracking.key=value]...
//
// Frames come from the rawlogs through io's SensorSync, as in `dynslam` (so the gyro samples
// and the extrinsics are the rawlog's). With --sim, each frame also gets the simulator's
// instance labels as object masks (a perfect segmentation: the fundamental-matrix RANSAC then
// sees only background candidates, as in the pipeline). Timing: wall clock of
// FeatureTracker::track per frame (grey image, pyramid, KLT both ways, RANSAC, new corners;
// not the rawlog reading), median over the frames after the first, compared with the issue's
// 3 ms target in the same run. Settings: the target's reference (kReferenceSettings), with --set
// over them.
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/Median.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/frontend/FeatureTracker.h>
#include <dynslam/frontend/FeatureTrackingStage.h>
#include <dynslam/frontend/SceneFlow.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

namespace {

using namespace dynslam;

constexpr double kTargetMs = 3.0;  // issue 5: extraction + tracking <= 3 ms per frame

/// The configuration the target was set for, which --set changes: 150 features (VINS-Fusion's),
/// a 15 px KLT window, none of the departures the whole system ships with (a residual gate,
/// occlusion and depth edges).
constexpr const char* kReferenceSettings =
    "[FeatureTracking]\nmax_features = 150\nklt_window_px = 15\nmax_klt_residual_ratio = 0\n"
    "occlusion_edge_radius_px = 0\ndepth_edge_radius_px = 0\n";

// The medians and percentiles of core/Median.h, as every bench reports them.
double median(const std::vector<double>& v) { return core::upperMedian(v); }
double percentile(const std::vector<double>& v, double q) { return core::upperPercentile(v, q); }

/// CPU time of the whole process (all threads), ms: what the tracker costs on a quiet machine
/// even when other processes share the cores (wall time then grows, CPU time does not).
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

/// The 1-minute load average, to put the wall times in context.
double loadAverage() {
  double load[1] = {0};
  return getloadavg(load, 1) == 1 ? load[0] : -1;
}

/// The simulator's truth for one frame: instance labels and the camera pose.
struct SimTruth {
  std::string dir;
  core::Trajectory poses;  // groundtruth.tum, one per frame

  cv::Mat labels(size_t index) const {
    char name[32];
    std::snprintf(name, sizeof name, "/labels/%06zu.png", index);
    cv::Mat l = cv::imread(dir + name, cv::IMREAD_UNCHANGED);
    if (l.type() != CV_16UC1) throw std::runtime_error("cannot read 16-bit labels " + dir + name);
    return l;
  }
};

std::vector<core::ObjectMask> masksFromLabels(const cv::Mat& labels) {
  std::map<uint16_t, cv::Rect> boxes;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (const uint16_t id = labels.at<uint16_t>(r, c)) boxes[id] |= cv::Rect(c, r, 1, 1);
  std::vector<core::ObjectMask> masks;
  for (const auto& [id, box] : boxes) {
    core::ObjectMask m;
    m.roi = box;
    m.mask = labels(box) == id;
    m.valid = true;
    masks.push_back(m);
  }
  return masks;
}

struct Figures {
  size_t frames = 0, features = 0, gyro_frames = 0;
  size_t incoming = 0, lost_klt = 0, lost_fb = 0, lost_residual = 0, lost_ransac = 0;
  std::vector<double> ms, cpu_ms, ms_pyramid, ms_klt, ms_ransac, ms_detect;
  std::vector<double> cells_computed;
  std::vector<double> completed_lengths;  // frames each track lasted
  double age_sum = 0;                     // sum of track_length over all output features
  std::vector<double> static_errors;      // px, --sim only
  cv::Size image;
};

/// Where a static point seen at `pixel` with `depth` in one frame appears in the next.
cv::Point2d reproject(const cv::Point2f& pixel, double depth, const core::CameraIntrinsics& K,
                      const Eigen::Isometry3d& T_world_from, const Eigen::Isometry3d& T_world_to) {
  const Eigen::Vector3d q =
      T_world_to.inverse() * (T_world_from * frontend::backProject(pixel, depth, K));
  const Eigen::Vector2d uv = frontend::project(q, K);
  return {uv.x(), uv.y()};
}

/// What a run carries from frame to frame.
struct RunState {
  Figures fig;
  std::map<int64_t, core::Feature> previous;  ///< the last frame's features, by id
  cv::Mat previousLabels;
};

/// One frame's timings and losses (timings from the second frame on).
void addFrame(Figures& fig, const frontend::FeatureTrackerStats& s, const core::Frame& frame,
              size_t features, double ms, double cpuMs) {
  fig.image = frame.rgb.size();
  if (fig.frames > 0) {
    fig.ms.push_back(ms);
    fig.cpu_ms.push_back(cpuMs);
    fig.ms_pyramid.push_back(s.ms_pyramid);
    fig.ms_klt.push_back(s.ms_klt);
    fig.ms_ransac.push_back(s.ms_ransac);
    fig.ms_detect.push_back(s.ms_detect);
    fig.cells_computed.push_back(s.cells_computed);
  }
  ++fig.frames;
  fig.features += features;
  fig.gyro_frames += s.gyro_used;
  fig.incoming += size_t(s.incoming);
  fig.lost_klt += size_t(s.lost_klt);
  fig.lost_fb += size_t(s.lost_fb);
  fig.lost_residual += size_t(s.lost_residual);
  fig.lost_ransac += size_t(s.lost_ransac);
}

/// The tracks' ages and ends, and (--sim) the static features' errors against the true motion.
void addTracks(RunState& st, const std::vector<core::Feature>& features, const core::Frame& frame,
               const cv::Mat& labels, const std::optional<SimTruth>& truth) {
  std::map<int64_t, core::Feature> current;
  for (const auto& f : features) {
    current[f.id] = f;
    st.fig.age_sum += f.track_length;
    const auto it = st.previous.find(f.id);
    if (!truth || it == st.previous.end() || it->second.depth <= 0) continue;
    const auto& before = it->second;
    const auto at = [](const cv::Mat& l, const cv::Point2f& p) {
      return l.at<uint16_t>(cvRound(p.y), cvRound(p.x));
    };
    if (at(st.previousLabels, before.pixel) != 0 || at(labels, f.pixel) != 0) continue;
    const cv::Point2d expected = reproject(before.pixel, before.depth, frame.intrinsics,
                                           truth->poses.at(frame.index - 1).T_world_body,
                                           truth->poses.at(frame.index).T_world_body);
    st.fig.static_errors.push_back(cv::norm(expected - cv::Point2d(f.pixel)));
  }
  for (const auto& [id, f] : st.previous)
    if (!current.count(id)) st.fig.completed_lengths.push_back(f.track_length);
  st.previous = std::move(current);
  st.previousLabels = labels;
}

void trackFrame(core::Frame& frame, frontend::FeatureTracker& tracker,
                const std::optional<SimTruth>& truth, RunState& st) {
  cv::Mat labels;
  if (truth) {
    labels = truth->labels(frame.index);
    frame.object_masks = masksFromLabels(labels);
  }
  const double cpuStart = processCpuMs();
  const auto start = std::chrono::steady_clock::now();
  const auto features = tracker.track(frame);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double cpuMs = processCpuMs() - cpuStart;
  addFrame(st.fig, tracker.lastStats(), frame, features.size(), ms, cpuMs);
  addTracks(st, features, frame, labels, truth);
}

Figures run(const std::string& rawlog, const frontend::FeatureTrackerParams& params,
            long long maxFrames, const std::optional<SimTruth>& truth) {
  // On this thread, not io::FrameReader's: the stage's time is taken as the process's CPU time,
  // which a reading thread would add to.
  io::RawlogSource source(rawlog);
  io::SensorSync sync;
  frontend::FeatureTracker tracker(params);
  RunState st;
  std::vector<core::Frame> ready;
  bool done = false;
  while (!done) {
    auto obs = source.next();
    ready.clear();
    if (obs)
      sync.push(obs, ready);
    else
      sync.flush(ready);
    for (auto& f : ready) {
      if (done) continue;
      if (maxFrames >= 0 && static_cast<long long>(st.fig.frames) >= maxFrames)
        done = true;
      else
        trackFrame(f, tracker, truth, st);
    }
    if (!obs) break;
  }
  for (const auto& [id, f] : st.previous) st.fig.completed_lengths.push_back(f.track_length);
  return st.fig;
}

void print(const std::string& what, const Figures& f) {
  const double perFrame = double(std::max<size_t>(f.incoming, 1));
  double lengthSum = 0;
  for (double l : f.completed_lengths) lengthSum += l;
  std::printf("%s: %zu frames %dx%d, %.1f features/frame, gyro-predicted flow on %zu frames\n",
              what.c_str(), f.frames, f.image.width, f.image.height,
              double(f.features) / double(std::max<size_t>(f.frames, 1)), f.gyro_frames);
  std::printf(
      "  extraction + tracking: median %.2f ms/frame wall (90%% %.2f) -> %.2f of the %.0f ms "
      "target; CPU %.2f ms/frame -> %.2f of it\n",
      median(f.ms), percentile(f.ms, 0.9), median(f.ms) / kTargetMs, kTargetMs, median(f.cpu_ms),
      median(f.cpu_ms) / kTargetMs);
  std::printf(
      "  parts (wall, medians): grey+pyramid %.2f, KLT fwd+bwd %.2f, F-RANSAC %.2f, "
      "spacing+corners %.2f ms (%.0f of the grid's cells computed)\n",
      median(f.ms_pyramid), median(f.ms_klt), median(f.ms_ransac), median(f.ms_detect),
      median(f.cells_computed));
  std::printf(
      "  lost per frame: KLT %.1f %%, forward-backward %.1f %%, KLT residual %.1f %%, F-RANSAC "
      "%.1f %%\n",
      100.0 * double(f.lost_klt) / perFrame, 100.0 * double(f.lost_fb) / perFrame,
      100.0 * double(f.lost_residual) / perFrame, 100.0 * double(f.lost_ransac) / perFrame);
  std::printf(
      "  mean track length %.2f frames (%zu tracks, each counted once at its end); mean age of "
      "a frame's features %.2f frames\n",
      lengthSum / double(std::max<size_t>(f.completed_lengths.size(), 1)),
      f.completed_lengths.size(), f.age_sum / double(std::max<size_t>(f.features, 1)));
  if (!f.static_errors.empty())
    std::printf(
        "  static features vs true motion + depth: median %.3f px, 90%% %.3f px (%zu tracks)\n",
        median(f.static_errors), percentile(f.static_errors, 0.9), f.static_errors.size());
}

constexpr const char* kUsage =
    R"(usage: bench-frontend [--sim DIR] [--rawlog FILE.rawlog] [--max-frames N] [--threads N]
                      [--set FeatureTracking.key=value]...
       bench-frontend -h | --help

Feature tracking (method.md section 3): the time of FeatureTracker::track per frame at 640x480
(median over the frames after the first, against the 3 ms target) and the tracks' quality: on
a simulated sequence scored against its ground truth (the simulator's labels as perfect object
masks; static features against the true motion and depth), on a real rawlog by its own
consistency. Give --sim, --rawlog or both.

Options:
  --sim DIR                 a dynslam-sim output folder (sim.rawlog, labels/, groundtruth.tum)
  --rawlog FILE             any RGB-D rawlog (e.g. 7-Scenes from sevenscenes2rawlog)
  --max-frames N            frames of each input at most (default: all)
  --threads N               cv::setNumThreads(N) (default: OpenCV's, one per core)
  --set FeatureTracking.key=value
                            override a [FeatureTracking] key (repeatable)
  -h, --help                print this text and exit

Exit codes: 0 done, 1 bad input, 2 usage (also when neither --sim nor --rawlog is given).
)";

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-frontend", [&] {
    core::CommandLine cl({"--sim", "--rawlog", "--max-frames", "--threads"}, {}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested() || (!cl.has("--sim") && !cl.has("--rawlog"))) {
      std::cout << kUsage;
      return cl.helpRequested() ? 0 : 2;
    }
    std::ostringstream command;
    for (int i = 0; i < argc; ++i) command << (i ? " " : "") << argv[i];
    std::printf("command: %s\n", command.str().c_str());

    const auto cfg = core::IniConfig::fromText(kReferenceSettings, "--set");
    auto overridden = cfg;
    for (const auto& s : cl.all("--set")) overridden.applyOverride(s);
    frontend::FeatureTrackingOptions options;
    core::loadOptionsStrict(options, overridden, "FeatureTracking");
    const auto& p = options.tracker;
    std::printf(
        "FeatureTracking: max_features %d, min_distance_px %.0f, grid %dx%d, KLT window %d "
        "levels %d, flow_init %s, F-RANSAC %s\n",
        p.max_features, p.corners.min_distance_px, p.corners.grid_cols, p.corners.grid_rows,
        p.klt_window_px, p.klt_pyramid_levels, frontend::toString(p.flow_init).c_str(),
        p.fundamental_ransac ? "on" : "off");
    const long long maxFrames = cl.optionalInteger("--max-frames").value_or(-1);
    if (const auto threads = cl.optionalInteger("--threads")) cv::setNumThreads(int(*threads));
    std::printf("OpenCV threads: %d; load average at start %.2f on %d cores\n", cv::getNumThreads(),
                loadAverage(), cv::getNumberOfCPUs());
    if (cl.has("--sim")) {
      SimTruth truth{cl.required("--sim"), {}};
      truth.poses = core::readTum(truth.dir + "/groundtruth.tum");
      print("sim " + truth.dir, run(truth.dir + "/sim.rawlog", p, maxFrames, truth));
    }
    if (cl.has("--rawlog"))
      print(cl.required("--rawlog"), run(cl.required("--rawlog"), p, maxFrames, std::nullopt));
    return 0;
  });
}
