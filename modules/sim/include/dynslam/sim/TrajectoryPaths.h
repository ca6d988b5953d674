#pragma once
// Ready-made SplineTrajectory control points for the motions the scenes use: a handheld camera
// circling a room and a ground robot driving through waypoints. Both start at t = 0.
#include <dynslam/sim/SplineTrajectory.h>

#include <vector>

namespace dynslam::sim {

/// A handheld camera walking a circle around `center` while its body x axis looks at `look_at`
/// (yaw and pitch follow; roll stays 0), bobbing vertically by bob_amplitude * sin(2 pi f t).
///
/// Position at t: center + (radius cos(theta), radius sin(theta), height) + bob, with
/// theta = 2 pi t / period_s (negative period_s: clockwise). Because a B-spline approximates its
/// controls, the circle's radius and the bob amplitude are pre-scaled by 6 / (4 + 2 cos(phi))
/// (phi = phase advance per knot) so the curve passes through the intended circle and bob at
/// every knot; between knots the radius deviates by < 1e-4 of itself with >= 16 knots per turn
/// (3 % at the minimum of 4). Yaw is unwrapped, so multi-turn orbits are fine. The curve covers
/// [0, duration_s]; endTime() may exceed duration_s by up to one knot interval.
///
/// Throws std::invalid_argument for a non-positive radius, duration or knot interval, a zero
/// period, fewer than 4 knots per turn or per bob period (the spline cannot represent faster
/// motion; shorten knot_interval), or a look_at on the camera's vertical line.
SplineTrajectory makeOrbit(const Eigen::Vector3d& center, double radius, double height,
                           double period_s, double duration_s, const Eigen::Vector3d& look_at,
                           double bob_amplitude, double knot_interval,
                           double bob_frequency_hz = 0.5);

/// A ground robot driving the polyline through waypoints_xy at `speed` (m/s), body at constant
/// z = height, pitch = roll = 0, and yaw along the direction of travel. At t = 0 the robot is at
/// rest on the first waypoint and at endTime() at rest on the last one; the speed profile along
/// the polyline starts at t = knot_interval, lasts path_length / speed + ramp_s, and the curve
/// ends one to two knot intervals after it. ramp_s > 0 adds smoothstep speed ramps of that length
/// at both ends; with ramp_s = 0 the spline itself eases in and out over about two knots.
/// Corners are rounded over about two knot intervals (turn radius ~ speed * knot_interval), and
/// the yaw spline interpolates the rounded curve's own heading at every knot: no side slip on the
/// straights, and a few degrees between knots in sharp corners (~5 degrees in a 90-degree corner).
/// Near-reversals (corners close to 180 degrees) make it turn almost in place.
///
/// Throws std::invalid_argument for fewer than 2 distinct waypoints, a non-positive speed or
/// knot interval, a negative ramp, or a path too short for both ramps (length < speed * ramp_s).
SplineTrajectory makeDrivePath(const std::vector<Eigen::Vector2d>& waypoints_xy, double speed,
                               double height, double knot_interval, double ramp_s = 0.0);

/// Replaces each angle by the representative closest to its predecessor (removes 2 pi jumps).
void unwrapAngles(std::vector<double>& angles);

}  // namespace dynslam::sim
