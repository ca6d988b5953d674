#include "dynslam/nav/NavigationOptions.h"

namespace dynslam::nav {

void NavigationOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  v.key("camera_x", camera_x, Range::any(),
        "m; the colour camera's optical centre on the robot's base (x forward, y left, z up, "
        "origin on the floor below the centre of rotation)");
  v.key("camera_y", camera_y, Range::any(), "m");
  v.key("camera_z", camera_z, Range::above(0), "m; the camera's height above the floor");
  v.key("camera_yaw_deg", camera_yaw_deg, Range::closed(-180, 180),
        "deg; the optical axis turned left of the robot's x");
  v.key("camera_pitch_deg", camera_pitch_deg, Range::closed(-90, 90),
        "deg; the optical axis turned down");
  v.key("camera_roll_deg", camera_roll_deg, Range::closed(-180, 180),
        "deg; about the optical axis");
  v.key("frame_id", frame_id,
        "the frame id the navigator gets with the pose; its targets must name the same");
  v.key("obstacle_range_m", obstacle_range_m, Range::above(0),
        "m; obstacles farther from the robot are left out (the navigator's ref_distance * 1.1 is "
        "enough)");
  v.key("floor_clearance_m", floor_clearance_m, Range::above(0.01),
        "m; static map points lower than this are the floor; a footprint's lowest points lie here");
  v.key("max_obstacle_height_m", max_obstacle_height_m, Range::above(0),
        "m; static map points higher than this are left out, footprints reach no higher");
  v.key("static_cell_m", static_cell_m, Range::above(0),
        "m; one static map point per cell of this size and footprint_height_step_m band");
  v.key("gather_in_background", gather_in_background,
        "gather a new static map's points on a thread of their own while the previous set "
        "serves (false: inside senseObstacles, which then takes longer but repeats exactly)");
  v.key("obstacle_horizon_s", obstacle_horizon_s, Range::atLeast(0),
        "s; a moving object's footprint swept along its constant-velocity prediction for this "
        "long (0: its current footprint only)");
  v.key("moving_speed_m_s", moving_speed_m_s, Range::atLeast(0),
        "m/s; objects slower than this on the floor get their current footprint only");
  v.key("max_velocity_sigma_m_s", max_velocity_sigma_m_s, Range::above(0),
        "m/s; an object whose velocity is this unsure (the larger horizontal sigma, with a "
        "covariance) gets its current footprint only");
  v.key("footprint_min_radius_m", footprint_min_radius_m, Range::above(0),
        "m; a footprint's radius at least (else half the object's larger horizontal extent)");
  v.key("person_max_radius_m", person_max_radius_m, Range::above(0),
        "m; a person's footprint radius at most (an extent measured too wide, two bodies in one "
        "box, must not wall off the robot's way)");
  v.key("footprint_max_radius_m", footprint_max_radius_m, Range::above(0),
        "m; any other object's (a car's) footprint radius at most");
  v.key("footprint_spacing_m", footprint_spacing_m, Range::above(0),
        "m; between a footprint's points on its ring and between rings along the sweep");
  v.key("footprint_height_step_m", footprint_height_step_m, Range::above(0),
        "m; a footprint's ring repeats every this much up to the object's top");
  v.key("max_pose_gap_s", max_pose_gap_s, Range::above(0),
        "s; the robot's velocity is its last two poses' difference when they are at most this "
        "far apart, else zero");
}

}  // namespace dynslam::nav
