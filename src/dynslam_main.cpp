// dynslam: plays a rawlog through the stages an ini file configures and writes the trajectory.
#include "runner/LiveView.h"
#include "runner/RunConfiguration.h"
#include "runner/Runner.h"

#include <dynslam/core/CommandLine.h>

#include <glog/logging.h>

#include <iostream>

namespace {
const char* kUsage =
    R"(usage: dynslam --config FILE.ini --rawlog FILE.rawlog --out DIR [--set section.key=value]...
               [--max-frames N] [--gt GT.tum] [--frames DIR [--no-video]] [--realtime]
               [--no-map] [--map-every N] [--map-voxel M] [--quiet]
               [--gui [--gui-rate HZ] [--gui-screenshot FILE.png]]
       dynslam --config FILE.ini [--set section.key=value]... --print-config

Plays FILE.rawlog (RGB-D CObservation3DRangeScan, CObservationIMU, CObservationGPS; observation
or action/sensory-frame layout) through the stages listed in [pipeline] stages of FILE.ini, and
writes in DIR:
  trajectory.tum   camera poses (timestamp tx ty tz qx qy qz qw), written as they are estimated
  objects/ID.tum   the world pose of each object the estimator follows (track id ID), same format
  summary.json     status, counts per observation type, frames, fps, per-stage median times
                   (and "ape" with --gt)
  timing.csv       one row per frame: frame,t_s,<stage>_ms for every stage,pipeline_ms
  keyframes.csv    with the estimator, one row per keyframe: frame,t_s, why it is one (first,
                   parallax, interval, few_shared), static / shared / non-rigid features,
                   rigid objects, solve_ms, iterations, restarted, visual_inertial, then its
                   velocity and accelerometer / gyroscope biases after the solve
  map.3Dscene      for SceneViewer3D (MRPT COpenGLScene): "static_map", a coloured point cloud
                   of the depth outside object masks (one frame in --map-every N, default 10;
                   one point per --map-voxel M cube, default 0.05 m), "camera_trajectory" (black
                   polyline) and "object_ID" (the poses of objects/ID.tum, one colour per object)
--gt GT.tum scores trajectory.tum against a TUM ground truth as `dynslam-eval ape GT.tum
trajectory.tum --align se3` does (evo's APE, translation, SE(3) Umeyama alignment, stamps
associated within 0.01 s), prints the RMSE and writes the statistics into summary.json.
--frames DIR also writes DIR/NNNNNN.png per frame: the colour image with the detector boxes, the
object masks, the tracks (id, class, depth) and the features by class (green static, orange
rigid, magenta non-rigid) drawn on it, and the same pictures as the video DIR/annotated.avi
(Motion-JPEG in AVI, written by OpenCV itself without FFmpeg, at the camera's frame rate;
--no-video: PNGs only).
--realtime plays the rawlog at camera rate (frames handed over as their stamps say), as a live
camera would; with [Detection] mode = realtime the detector thread then runs at the rate it can
keep, and summary.json gets "realtime" (lag behind the camera) and the detector's rate.
--gui opens a live MRPT 3-D window (needs an X display; without one: xvfb-run -a dynslam --gui
...) showing what map.3Dscene will hold (static map, black camera trajectory, object tracks),
the current camera as axes and the annotated picture of the frame (as --frames draws it) in the
lower-left corner; redrawn at most --gui-rate HZ times a second (default 10), the map, trajectory
and tracks at most once a second, so the stages are barely slowed (about 5% fewer FPS). Closing
the window does not stop the run: it goes on without the window and writes every output. The
window closes when the run ends (map.3Dscene keeps the result for SceneViewer3D).
--gui-screenshot FILE.png (implies --gui) writes the window's final picture (read back from the
window, or drawn off-screen from the window's viewpoint where software OpenGL reads the window
back black).
--set overrides one ini value (repeatable). Unknown keys, sections and stage names are errors.
--print-config configures the stages as a run would and prints the configuration it would run
with, as an ini (every key of every section read, the ini's values and the defaults of the rest,
each with its meaning), then exits; nothing is read or written.
Exit codes: 0 ok, 1 bad input or configuration (outputs hold what was done), 2 usage, 130 Ctrl-C.
)";
}  // namespace

int main(int argc, char** argv) {
  // Ceres logs through glog: without this, every run starts with glog's "Logging before
  // InitGoogleLogging" banner and a solve that tries an invalid step (a point behind a camera)
  // prints a warning per try, dozens per run. The estimator counts and reports its own failures
  // (summary.json); only glog errors still reach stderr.
  google::InitGoogleLogging(argv[0]);
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_ERROR;
  return dynslam::core::runProgram("dynslam", [&] {
    dynslam::core::CommandLine cl(
        {"--config", "--rawlog", "--out", "--max-frames", "--frames", "--gt", "--map-every",
         "--map-voxel", "--gui-rate", "--gui-screenshot"},
        {"--quiet", "--realtime", "--no-video", "--no-map", "--gui", "--print-config"}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    if (cl.has("--print-config")) {
      dynslam::runner::printEffectiveConfig(cl.required("--config"), cl.all("--set"), std::cout);
      return 0;
    }
    dynslam::runner::RunnerArgs args;
    args.config = cl.required("--config");
    args.rawlog = cl.required("--rawlog");
    args.out = cl.required("--out");
    args.overrides = cl.all("--set");
    args.max_frames = cl.optionalInteger("--max-frames").value_or(-1);
    args.quiet = cl.has("--quiet");
    args.frames_dir = cl.valueOr("--frames", "");
    args.realtime = cl.has("--realtime");
    args.frames_video = !cl.has("--no-video");
    args.ground_truth = cl.valueOr("--gt", "");
    args.map = !cl.has("--no-map");
    args.map_every_n_frames =
        static_cast<int>(cl.optionalInteger("--map-every").value_or(args.map_every_n_frames));
    args.map_voxel_size = cl.optionalDouble("--map-voxel").value_or(args.map_voxel_size);
    if (args.map_every_n_frames < 1 || !(args.map_voxel_size > 0))
      throw dynslam::core::UsageError("--map-every must be >= 1 and --map-voxel > 0");
    args.gui_screenshot = cl.valueOr("--gui-screenshot", "");
    args.gui = cl.has("--gui") || !args.gui_screenshot.empty();
    args.gui_max_rate_hz = cl.optionalDouble("--gui-rate").value_or(args.gui_max_rate_hz);
    if (!(args.gui_max_rate_hz > 0)) throw dynslam::core::UsageError("--gui-rate must be > 0");
    // Before any work: a run that cannot show its window fails at once, saying why.
    if (args.gui) {
      if (const auto problem = dynslam::runner::LiveView::displayProblem(); !problem.empty())
        throw std::runtime_error(problem);
    }
    return dynslam::runner::runDynslam(args);
  });
}
