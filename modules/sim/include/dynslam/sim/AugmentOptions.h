#pragma once
// [Augment]: the real sequence that augment mode inserts rendered people and cars into
// (Augmenter.h), and how its floor, its free floor and its smoothed trajectory are found.
// Keys, ranges, meanings: describe() in AugmentOptions.cpp; docs/parameters.md.
#include <dynslam/core/Options.h>

#include <string>

namespace dynslam::sim {

struct AugmentOptions : core::Options {
  std::string rawlog;
  std::string groundtruth;
  double knot_interval = 0.1;

  // The floor plane.
  int floor_frames = 40;
  int floor_pixel_step = 4;
  double floor_max_depth = 3.5;
  double floor_inlier_distance = 0.02;
  int floor_ransac_iterations = 500;
  double floor_max_tilt_deg = 30.0;

  // The free floor and where the agents go on it.
  double map_cell = 0.05;
  double obstacle_height = 0.10;
  double clearance = 0.15;
  double region_radius = 2.0;
  double min_walk_length = 0.8;
  double camera_clearance = 0.5;

  void describe(core::OptionVisitor& v) override;
  /// Throws core::ConfigError naming the first [Augment] key out of its range or an empty
  /// rawlog: what augment mode needs (loading checks the ranges already; options set in code
  /// are checked here).
  void validate() const;
};

}  // namespace dynslam::sim
