#include "dynslam/sim/AugmentOptions.h"

#include <dynslam/core/Config.h>

#include <mrpt/config/CConfigFileBase.h>

#include <sstream>

namespace dynslam::sim {

// Every key is documented in AugmentOptions.h and, one line each, in the saved ini below.
void AugmentOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
  MRPT_LOAD_CONFIG_VAR(rawlog, string, c, s);       // relative: against the working directory
  MRPT_LOAD_CONFIG_VAR(groundtruth, string, c, s);  // empty: <rawlog stem>.gt.tum
  MRPT_LOAD_CONFIG_VAR(knot_interval, double, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_frames, int, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_pixel_step, int, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_max_depth, double, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_inlier_distance, double, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_ransac_iterations, int, c, s);
  MRPT_LOAD_CONFIG_VAR(floor_max_tilt_deg, double, c, s);
  MRPT_LOAD_CONFIG_VAR(map_cell, double, c, s);
  MRPT_LOAD_CONFIG_VAR(obstacle_height, double, c, s);
  MRPT_LOAD_CONFIG_VAR(clearance, double, c, s);
  MRPT_LOAD_CONFIG_VAR(region_radius, double, c, s);
  MRPT_LOAD_CONFIG_VAR(min_walk_length, double, c, s);
  MRPT_LOAD_CONFIG_VAR(camera_clearance, double, c, s);
}

void AugmentOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
  MRPT_SAVE_CONFIG_VAR_COMMENT(rawlog, "sevenscenes2rawlog output (relative: working directory)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(groundtruth, "TUM ground truth; empty: <rawlog stem>.gt.tum");
  MRPT_SAVE_CONFIG_VAR_COMMENT(knot_interval, "s between control points of the IMU spline");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_frames, "frames sampled for the floor and the free floor");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_pixel_step, "every n-th pixel in x and y");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_max_depth, "m; farther depth is too noisy for the floor");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_inlier_distance, "m; RANSAC inlier distance");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_ransac_iterations, "RANSAC draws");
  MRPT_SAVE_CONFIG_VAR_COMMENT(floor_max_tilt_deg, "deg between the floor and the cameras' up");
  MRPT_SAVE_CONFIG_VAR_COMMENT(map_cell, "m; cell of the free-floor grid");
  MRPT_SAVE_CONFIG_VAR_COMMENT(obstacle_height, "m above the floor from which points block");
  MRPT_SAVE_CONFIG_VAR_COMMENT(clearance, "m kept between agents' floor and real obstacles");
  MRPT_SAVE_CONFIG_VAR_COMMENT(region_radius, "m around the most-seen clear floor");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_walk_length, "m; shortest straight walk");
  MRPT_SAVE_CONFIG_VAR_COMMENT(camera_clearance, "m kept between agents and the camera");
}

void AugmentOptions::validate() const {
  const auto check = [](bool ok, const char* key, double value, const char* rule) {
    if (ok) return;
    std::ostringstream msg;
    msg << "[Augment] " << key << " = " << value << ": must be " << rule;
    throw core::ConfigError(msg.str());
  };
  if (rawlog.empty()) throw core::ConfigError("[Augment] rawlog is empty: name the real sequence");
  check(knot_interval > 0, "knot_interval", knot_interval, "> 0 s");
  check(floor_frames >= 1, "floor_frames", floor_frames, ">= 1");
  check(floor_pixel_step >= 1, "floor_pixel_step", floor_pixel_step, ">= 1");
  check(floor_max_depth > 0, "floor_max_depth", floor_max_depth, "> 0 m");
  check(floor_inlier_distance > 0, "floor_inlier_distance", floor_inlier_distance, "> 0 m");
  check(floor_ransac_iterations >= 1, "floor_ransac_iterations", floor_ransac_iterations, ">= 1");
  check(floor_max_tilt_deg > 0 && floor_max_tilt_deg < 90, "floor_max_tilt_deg", floor_max_tilt_deg,
        "in (0, 90) deg");
  check(map_cell > 0, "map_cell", map_cell, "> 0 m");
  check(obstacle_height > 0, "obstacle_height", obstacle_height, "> 0 m");
  check(clearance >= 0, "clearance", clearance, ">= 0 m");
  check(region_radius > 0, "region_radius", region_radius, "> 0 m");
  check(min_walk_length > 0, "min_walk_length", min_walk_length, "> 0 m");
  check(camera_clearance >= 0, "camera_clearance", camera_clearance, ">= 0 m");
}

}  // namespace dynslam::sim
