#pragma once
// [Augment]: the real sequence that augment mode inserts rendered people and cars into
// (Augmenter.h), and how its floor, its free floor and its smoothed trajectory are found.
#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace dynslam::sim {

struct AugmentOptions : mrpt::config::CLoadableOptions {
  /// Rawlog written by sevenscenes2rawlog (RGB-D observations). Relative paths resolve against
  /// the working directory, like every path on dynslam's command lines.
  std::string rawlog;
  /// Its ground truth (TUM, camera-to-world). Empty: the rawlog's path with ".rawlog" replaced
  /// by ".gt.tum", the file sevenscenes2rawlog writes beside it.
  std::string groundtruth;
  /// s between control points of the B-spline fitted to the ground truth for the IMU. Longer
  /// smooths more pose jitter but follows quick hand motion less closely.
  double knot_interval = 0.1;

  /// Floor plane: RANSAC over the depth of floor_frames frames spread over the sequence, every
  /// floor_pixel_step-th pixel up to floor_max_depth (m); inliers within floor_inlier_distance
  /// (m); normals within floor_max_tilt_deg of the cameras' mean "up" (minus their image-down
  /// axis: hand-held and robot cameras are held roughly upright).
  int floor_frames = 40;
  int floor_pixel_step = 4;
  double floor_max_depth = 3.5;
  double floor_inlier_distance = 0.02;
  int floor_ransac_iterations = 500;
  double floor_max_tilt_deg = 30.0;

  /// Free floor: a grid of map_cell (m) cells; a cell is clear when the real depth showed bare
  /// floor there and nothing from obstacle_height to 2 m above it, and no other cell is within
  /// clearance (m) of it (what a body keeps from a table's edge).
  double map_cell = 0.05;
  double obstacle_height = 0.10;
  double clearance = 0.15;
  /// Agents use clear floor within region_radius (m) of the clear cell the camera sees most;
  /// walkers need straight clear runs of min_walk_length (m) and every agent keeps
  /// camera_clearance (m) from the camera at every frame.
  double region_radius = 2.0;
  double min_walk_length = 0.8;
  double camera_clearance = 0.5;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
  /// Throws core::ConfigError naming the first [Augment] key out of its range (an empty rawlog,
  /// a non-positive size or count, a negative clearance).
  void validate() const;
};

}  // namespace dynslam::sim
