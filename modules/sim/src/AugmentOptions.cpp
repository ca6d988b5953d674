#include "dynslam/sim/AugmentOptions.h"

#include <dynslam/core/Config.h>

#include <stdexcept>

namespace dynslam::sim {

void AugmentOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  const Range positive = Range::above(0), count = Range::atLeast(1), off = Range::atLeast(0);
  v.path("rawlog", rawlog,
         "the real sequence: a sevenscenes2rawlog output (RGB-D observations); relative: from "
         "the working directory, else the ini's folder");
  v.path("groundtruth", groundtruth,
         "its ground truth (TUM, camera-to-world); empty: the rawlog's path with .rawlog replaced "
         "by .gt.tum, the file sevenscenes2rawlog writes beside it");
  v.key("knot_interval", knot_interval, positive,
        "s between control points of the B-spline fitted to the ground truth for the IMU (longer "
        "smooths more pose jitter but follows quick hand motion less closely)");
  v.key("floor_frames", floor_frames, count,
        "frames spread over the sequence whose depth the floor plane and the free floor are "
        "found in");
  v.key("floor_pixel_step", floor_pixel_step, count, "every n-th pixel in x and y");
  v.key("floor_max_depth", floor_max_depth, positive,
        "m; farther depth is too noisy for the floor");
  v.key("floor_inlier_distance", floor_inlier_distance, positive, "m; RANSAC inlier distance");
  v.key("floor_ransac_iterations", floor_ransac_iterations, count, "RANSAC draws");
  v.key("floor_max_tilt_deg", floor_max_tilt_deg, Range{0, 90, true, true},
        "deg between the floor's normal and the cameras' mean up (minus their image-down axis: "
        "hand-held and robot cameras are held roughly upright)");
  v.key("map_cell", map_cell, positive, "m; cell of the free-floor grid");
  v.key("obstacle_height", obstacle_height, positive,
        "m above the floor from which points block a cell (up to 2 m); a cell is clear when the "
        "real depth showed bare floor there and nothing blocking");
  v.key("clearance", clearance, off,
        "m kept between the agents' floor and real obstacles (what a body keeps from a table's "
        "edge)");
  v.key("region_radius", region_radius, positive,
        "m; agents use clear floor within this of the clear cell the camera sees most");
  v.key("min_walk_length", min_walk_length, positive, "m; shortest straight clear walk");
  v.key("camera_clearance", camera_clearance, off,
        "m kept between every agent and the camera at every frame");
}

void AugmentOptions::validate() const {
  if (rawlog.empty()) throw core::ConfigError("[Augment] rawlog is empty: name the real sequence");
  try {
    check();
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError(std::string("[Augment] ") + e.what());
  }
}

}  // namespace dynslam::sim
