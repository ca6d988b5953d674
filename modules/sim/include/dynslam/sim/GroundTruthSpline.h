#pragma once
// A SplineTrajectory fitted by least squares to stamped poses (a real sequence's ground truth),
// so an IMU can be synthesised for a real camera motion: the spline has the analytic
// derivatives the IMU needs and smooths the jitter of the recorded poses, which double
// differentiation would otherwise turn into accelerations of several g.
#include <dynslam/core/Trajectory.h>
#include <dynslam/sim/SplineTrajectory.h>

#include <Eigen/Geometry>

#include <vector>

namespace dynslam::sim {

/// Uniform cubic B-spline with knots every `knot_interval` s from poses[0].t, covering up to the
/// last pose. Positions and ZYX yaw/pitch/roll (unwrapped along the sequence) are fitted per
/// channel by linear least squares, with a faint penalty on the controls' second differences
/// (1e-6 of the data weight) so knot intervals without poses stay well defined. Throws
/// std::invalid_argument for fewer than 2 poses, times not strictly increasing, a
/// non-positive knot interval, or a pitch within 5 deg of +-90 (where ZYX angles degenerate).
SplineTrajectory fitSplineToPoses(const core::Trajectory& poses, double knot_interval);

/// How far a spline is from stamped poses of a sensor rigidly mounted at T_body_sensor on the
/// spline's body (Identity: the body poses it was fitted to): position error in m and rotation
/// error in rad, over all poses.
struct SplineFitError {
  double median_position = 0, max_position = 0;
  double median_rotation = 0, max_rotation = 0;
};
SplineFitError splineFitError(
    const SplineTrajectory& spline, const core::Trajectory& sensor_poses,
    const Eigen::Isometry3d& T_body_sensor = Eigen::Isometry3d::Identity());

}  // namespace dynslam::sim
