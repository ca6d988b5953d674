#pragma once
// [Navigation]: how the navigation adapter turns the SLAM estimate into what MRPT's reactive
// navigator senses (NavigationAdapter.h): where the camera sits on the robot, which static map
// points are obstacles, and how far ahead a moving object's footprint is swept.
#include <dynslam/core/Options.h>

#include <string>

namespace dynslam::nav {

struct NavigationOptions : core::Options {
  static constexpr const char* kSection = "Navigation";

  /// The colour camera's optical frame on the robot's base (x forward, y left, z up, origin on
  /// the floor below the robot's centre of rotation), as core::opticalFrameOnBody takes it.
  double camera_x = 0, camera_y = 0, camera_z = 0.5;
  double camera_yaw_deg = 0, camera_pitch_deg = 0, camera_roll_deg = 0;
  /// The frame id the navigator gets with the pose (its targets' frame id must match).
  std::string frame_id = "map";

  double obstacle_range_m = 4.0;       ///< obstacles farther from the robot are left out
  double floor_clearance_m = 0.05;     ///< static map points lower than this are the floor
  double max_obstacle_height_m = 2.0;  ///< static map points higher than this are left out
  double static_cell_m = 0.05;         ///< one static point per cell of this size (and height band)
  /// A new static map's points are gathered on a thread of its own while the previous set
  /// serves (false: inside senseObstacles, for repeatable runs).
  bool gather_in_background = true;

  /// s; each moving object's footprint is swept along its constant-velocity prediction for this
  /// long (0: its current footprint only).
  double obstacle_horizon_s = 1.0;
  double moving_speed_m_s = 0.2;  ///< objects slower than this are not swept
  /// m/s; an object whose speed is this unsure (the larger horizontal sigma of its velocity,
  /// when the system gives a covariance) is not swept: a state just made, or one the filter
  /// cannot follow, would sweep its footprint the wrong way.
  double max_velocity_sigma_m_s = 0.5;
  double footprint_min_radius_m = 0.25;  ///< a footprint's radius at least (else half its width)
  /// At most: a person's (a wrong extent, two bodies in one box, must not wall off the room)
  /// and any other object's (a car's).
  double person_max_radius_m = 0.4;
  double footprint_max_radius_m = 2.5;
  double footprint_spacing_m = 0.1;      ///< points on a footprint's ring, rings along the sweep
  double footprint_height_step_m = 0.3;  ///< a footprint's points repeat every this much up
  /// s; the robot's velocity comes from its last two poses when they are at most this far apart
  /// (else it is reported at rest).
  double max_pose_gap_s = 0.5;

  void describe(core::OptionVisitor& v) override;
};

}  // namespace dynslam::nav
