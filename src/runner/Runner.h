#pragma once
// The rawlog playback of the `dynslam` program: the rawlog's observations fed one by one into
// system::System, the output files as its sinks (trajectory written pose by pose), and a summary
// written whatever happens.
#include <string>
#include <vector>

namespace dynslam::runner {

struct RunnerArgs {
  std::string config;                  ///< ini file
  std::string rawlog;                  ///< input
  std::string out;                     ///< output folder (created)
  std::vector<std::string> overrides;  ///< "section.key=value"
  long max_frames = -1;                ///< stop after this many frames (-1: all)
  bool quiet = false;                  ///< no progress output
  std::string frames_dir;    ///< non-empty: an annotated PNG per frame there (viz::AnnotatedFrame)
  bool frames_video = true;  ///< with frames_dir: also frames_dir/annotated.avi (Motion-JPEG)
  std::string ground_truth;  ///< non-empty: TUM file; APE (SE(3)-aligned) into summary.json
  bool map = true;           ///< write out/map.3Dscene (viz::MapSceneBuilder)
  int map_every_n_frames = 10;               ///< static points from one posed frame in this many
  double map_voxel_size = 0.05;              ///< m, the static map's voxel grid
  std::size_t map_max_points = 1000000;      ///< the static map's voxels at most
  std::size_t map_max_track_points = 20000;  ///< each trajectory line's points at most
  /// Play the rawlog at camera rate (each frame handed to the pipeline no earlier than its
  /// stamp says, relative to the first), as a live camera would; the lag behind that schedule
  /// goes into summary.json. Off: as fast as the stages go.
  bool realtime = false;
  /// A live 3-D window (LiveView: map, trajectory, objects, annotated frame), redrawn at most
  /// gui_max_rate_hz times a second. Closing it does not stop the run.
  bool gui = false;
  double gui_max_rate_hz = 10.0;
  std::string gui_screenshot;  ///< non-empty (with gui): the window's picture at the end, PNG
  /// Non-empty: live sensors from this ini (LiveSensors) instead of the rawlog.
  std::string sensors;
  std::string record;  ///< with sensors, non-empty: what they delivered, as a rawlog
  double sensor_timeout_s =
      5.0;  ///< with sensors: no observation for this long ends the run (0: wait)
};

/// Runs the whole job. Returns the process exit code: 0 on success, 1 when the input or the
/// configuration was bad (the message went to stderr; trajectory.tum and summary.json hold
/// what was done before the failure).
int runDynslam(const RunnerArgs& args);

}  // namespace dynslam::runner
