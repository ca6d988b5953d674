// dynslam: plays a rawlog through the stages an ini file configures and writes the trajectory.
#include <dynslam/system/RunConfiguration.h>
#include "runner/LiveView.h"
#include "runner/Runner.h"

#include <dynslam/core/CommandLine.h>

#include <glog/logging.h>

#include <iostream>

namespace {
const char* kUsage =
    R"(usage: dynslam --config FILE.ini --rawlog FILE.rawlog --out DIR [options]
       dynslam --config FILE.ini --sensors SENSORS.ini [--record FILE.rawlog] --out DIR [options]
       dynslam --config FILE.ini [--set Section.key=value]... --print-config
       dynslam -h | --help

Plays FILE.rawlog through the stages listed in [pipeline] stages of FILE.ini (detector ->
segmenter -> tracker -> front-end -> estimator, as the ini lists them) and writes the camera
trajectory, the objects' trajectories and the run's records in DIR.

Options:
  --config FILE.ini          the configuration: [pipeline] stages and each stage's section
                             (every key: docs/parameters.md)
  --rawlog FILE.rawlog       the input: RGB-D CObservation3DRangeScan, CObservationIMU,
                             CObservationGPS (GGA), in the observation or the
                             action/sensory-frame layout
  --sensors SENSORS.ini      live sensors instead of a rawlog: MRPT hwdrivers sensors, one
                             section each as rawlog-grabber reads them (driver = COpenNI2Sensor,
                             CKinect, CCameraSensor, CIMUXSens_MT4, CGPSInterface, or
                             CRawlogReplaySensor with rawlog = FILE; process_rate, sensorLabel),
                             each on a thread of its own; Ctrl-C ends the run with every output
                             written (params/live/)
  --record FILE.rawlog       with --sensors: also write what the sensors delivered as a rawlog
  --sensor-timeout S         with --sensors: no observation for S seconds ends the run as
                             failed, outputs kept (default 5; 0: wait for the sensors)
  --out DIR                  the output folder (created; files in it are replaced)
  --set Section.key=value    override one ini value (repeatable, applied in order); unknown
                             keys, sections and stage names are errors
  --max-frames N             stop after N frames (default: every frame)
  --gt GT.tum                score trajectory.tum against a TUM ground truth as dynslam-eval's
                             ape with SE(3) alignment does (evo's APE, translation, stamps
                             associated within 0.01 s); print the RMSE and write the statistics
                             into summary.json ("ape")
  --frames DIR               also write DIR/NNNNNN.png per frame: the colour image with the
                             detector boxes, the object masks, the tracks (id, class, depth)
                             and the features by class (green static, orange rigid, magenta
                             non-rigid), and the same pictures as DIR/annotated.avi
                             (Motion-JPEG at the camera's frame rate)
  --no-video                 with --frames: the PNGs only, no annotated.avi
  --realtime                 play the rawlog at camera rate (each frame handed over when its
                             stamp says), as a live camera would; with [Detection] mode =
                             realtime the detector thread runs at the rate it can keep;
                             summary.json gets "realtime" (lag behind the camera)
  --no-map                   do not write map.3Dscene
  --map-every N              the static map takes one posed frame in N (default 10)
  --map-voxel M              the static map keeps one point per M-metre cube (default 0.05)
  --map-max-points N         the static map's points at most; new cubes past it are refused
                             (default 1000000, about 64 MB)
  --map-track-points N       each trajectory line of the map (the camera's, each object's)
                             keeps at most N points: one reaching N keeps every second point
                             (default 20000)
  --quiet                    no progress line on stderr
  --gui                      a live MRPT 3-D window (needs an X display; without one:
                             xvfb-run -a dynslam --gui ...): what map.3Dscene will hold, the
                             current camera as axes and the annotated picture of the frame;
                             closing it does not stop the run, which writes every output
  --gui-rate HZ              redraw the window at most HZ times a second (default 10; the map,
                             trajectory and tracks at most once a second)
  --gui-screenshot FILE.png  (implies --gui) write the window's final picture to FILE.png
  --print-config             configure the stages as a run would and print the configuration
                             it would run with, as an ini (every key of every section read:
                             the ini's values and the defaults of the rest, each with its
                             meaning), then exit; nothing is read or written
  -h, --help                 print this text and exit

Outputs in DIR (formats: docs/programs.md):
  trajectory.tum   camera poses, "t tx ty tz qx qy qz qw", written as they are estimated
  objects/ID.tum   the world pose of each object the estimator follows (track id ID), same format
  summary.json     status, counts per observation type, frames, poses, FPS, per-stage median
                   times and statistics ("ape" with --gt, "realtime" with --realtime)
  timing.csv       one row per frame: frame,t_s,<stage>_ms for every stage,pipeline_ms
  keyframes.csv    with a pose estimator, one row per keyframe: why it is one, the features
                   and objects in the solve, solve time, velocity and IMU biases after it
  map.3Dscene      for SceneViewer3D: "static_map" (coloured points of the depth outside object
                   masks), "camera_trajectory" (black polyline), "object_ID" (one per object)
Exit codes: 0 ok, 1 bad input or configuration (the outputs hold what was done before the
error; summary.json says "failed" and why), 2 usage, 130 / 143 interrupted (Ctrl-C / SIGTERM;
outputs hold the frames done). Killed outright (kill -9), a run leaves every row written so far
whole and no summary.json (it is written whole or not at all).
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
         "--map-voxel", "--map-max-points", "--map-track-points", "--gui-rate", "--gui-screenshot",
         "--sensors", "--record", "--sensor-timeout"},
        {"--quiet", "--realtime", "--no-video", "--no-map", "--gui", "--print-config"}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    if (cl.has("--print-config")) {
      dynslam::system::printEffectiveConfig(cl.required("--config"), cl.all("--set"), std::cout);
      return 0;
    }
    dynslam::runner::RunnerArgs args;
    args.config = cl.required("--config");
    args.sensors = cl.valueOr("--sensors", "");
    if (args.sensors.empty() == !cl.has("--rawlog"))
      throw dynslam::core::UsageError("give --rawlog or --sensors, one of them");
    args.rawlog = cl.valueOr("--rawlog", "");
    args.record = cl.valueOr("--record", "");
    args.sensor_timeout_s = cl.optionalDouble("--sensor-timeout").value_or(args.sensor_timeout_s);
    if (!args.record.empty() && args.sensors.empty())
      throw dynslam::core::UsageError("--record goes with --sensors");
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
    const long long max_points = cl.optionalInteger("--map-max-points")
                                     .value_or(static_cast<long long>(args.map_max_points));
    const long long track_points = cl.optionalInteger("--map-track-points")
                                       .value_or(static_cast<long long>(args.map_max_track_points));
    if (max_points < 1 || track_points < 2)
      throw dynslam::core::UsageError("--map-max-points must be >= 1 and --map-track-points >= 2");
    args.map_max_points = static_cast<std::size_t>(max_points);
    args.map_max_track_points = static_cast<std::size_t>(track_points);
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
