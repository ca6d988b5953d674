// dynslam: plays a rawlog through the stages an ini file configures and writes the trajectory.
#include "runner/Runner.h"

#include <dynslam/core/CommandLine.h>

#include <iostream>

namespace {
const char* kUsage =
    R"(usage: dynslam --config FILE.ini --rawlog FILE.rawlog --out DIR [--set section.key=value]...
               [--max-frames N] [--frames DIR] [--realtime] [--quiet]

Plays FILE.rawlog (RGB-D CObservation3DRangeScan, CObservationIMU, CObservationGPS; observation
or action/sensory-frame layout) through the stages listed in [pipeline] stages of FILE.ini, and
writes in DIR:
  trajectory.tum   camera poses (timestamp tx ty tz qx qy qz qw), written as they are estimated
  objects/ID.tum   the world pose of each object the estimator follows (track id ID), same format
  summary.json     status, counts per observation type, frames, fps, per-stage median times
--frames DIR also writes DIR/NNNNNN.png per frame: the colour image with the detector boxes, the
object masks and the tracks (id, class, depth) drawn on it.
--realtime plays the rawlog at camera rate (frames handed over as their stamps say), as a live
camera would; with [Detection] mode = realtime the detector thread then runs at the rate it can
keep, and summary.json gets "realtime" (lag behind the camera) and the detector's rate.
--set overrides one ini value (repeatable). Unknown keys, sections and stage names are errors.
Exit codes: 0 ok, 1 bad input or configuration (outputs hold what was done), 2 usage, 130 Ctrl-C.
)";
}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("dynslam", [&] {
    dynslam::core::CommandLine cl({"--config", "--rawlog", "--out", "--max-frames", "--frames"},
                                  {"--quiet", "--realtime"}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
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
    return dynslam::runner::runDynslam(args);
  });
}
