#pragma once
// RGB-D + IMU initialization (method.md section 5 'Initialization', issue 6 item 5): from the
// first keyframes' visual body poses, which carry metric scale because RGB-D measures depth,
// and the IMU preintegrations between them, estimate what the visual odometry cannot give the
// sliding window: the gyroscope bias, the gravity vector in the visual world frame and every
// keyframe's velocity. This is VINS-Mono's visual-inertial alignment (initial_aligment.cpp)
// with the scale fixed to 1:
//  1. Gyroscope bias: least squares on the relative rotations, gamma_k(bg) ~ R_i^T R_j, using
//     the preintegration's d(gamma)/d(bg) Jacobian; Gauss-Newton, repropagating the
//     preintegrations at each new estimate (VINS does one step; iterating makes the result exact
//     for exact data even when the bias is beyond the first-order range).
//  2. Linear alignment with the IMU conventions of ImuPreintegration.h, for each pair i, j = i+1
//     (T = the preintegration's sumDt, R_i, p_i the visual pose, all in the visual world):
//         T v_i + 1/2 T^2 g      = p_j - p_i - R_i alpha
//         v_j - v_i - T g        = R_i beta
//     unknowns the world velocities v_0..v_{N-1} and g (3N + 3), unweighted as VINS.
//  3. Gravity refinement on the sphere |g| = gravity_magnitude: g = |g| n + B w with B a basis of
//     the tangent plane at n, a few linear solves for (v, w) (VINS RefineGravity), then the
//     velocities solved once more with g fixed on the sphere.
//
// What can and cannot be checked. With the scale known, the matrix of step 2 holds only the
// interval lengths T (the velocities are world-frame unknowns): its condition number does not
// depend on the motion at all, and gravity and velocities are determined even for a still
// sequence. So there is no condition-number test to make. The checks made are:
//  - consistency: |g| of the free solve of step 2 against gravity_magnitude, and the RMS of the
//    position and velocity residuals after refinement (a time offset or a broken visual
//    odometry show here);
//  - the visual scale: step 2 solved once more with the scale s of the visual displacements
//    free (VINS's monocular unknown), s and its standard error from the residual. A depth scale
//    20 % off moves |g_free| by only 0.02 m/s^2 and the residual by 1 cm (the velocities absorb
//    it), but s by 20 %; refused when |s - 1| exceeds both max_scale_error and
//    scale_significance sigma. Here the motion matters: without acceleration, s is
//    unobservable (NaN, check skipped);
//  - excitation: the RMS over the intervals of the mean world acceleration, R_i beta / T + g.
//    This is a policy, not a mathematical need: a still or constant-velocity start gives good
//    gravity and velocities here, but the consistency checks above cannot test anything then
//    (nothing moves for the IMU and the visual odometry to disagree on). Set
//    min_acceleration_rms = 0 to accept still starts.
// The accelerometer bias is not estimated (as VINS): its component across gravity is taken as
// a tilt of g (|ba| / |g| rad, ~0.8 deg for EuRoC's 0.14 m/s^2); only rotating the body
// separates them, which the sliding window does later. Estimated here too, it made the worst
// windows worse (docs/notes/estimator.md, 2026-11-28 (accelerometer bias)).
//
// Using the result: with R = R_gravity_world, the gravity-aligned states are R T_world_body,
// R v_world, and gravity (0, 0, -gravity_magnitude); the gyro bias as estimated, the
// accelerometer bias the preintegrations' linearisation point.
#include <dynslam/estimator/imu/ImuPreintegration.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace dynslam::estimator {

struct ImuInitializerOptions {
  double gravity_magnitude = 9.81;       ///< m/s^2, the radius of the refinement's sphere
  int gyro_bias_iterations = 5;          ///< Gauss-Newton steps at most (stops when converged)
  int gravity_refine_iterations = 4;     ///< VINS RefineGravity uses 4
  double max_interval_mismatch = 0.005;  ///< s, |t_j - t_i - sumDt| allowed per pair
  double max_gravity_norm_error = 0.5;   ///< m/s^2, | |g_free| - gravity_magnitude |
  double max_position_rms = 0.05;        ///< m, RMS of the position residuals
  double max_velocity_rms = 0.10;        ///< m/s, RMS of the velocity residuals
  double max_scale_error = 0.10;         ///< |visual_scale - 1| refused above this ...
  double scale_significance = 3;         ///< ... and above this many visual_scale_sigma
  double visual_position_noise = 0.01;   ///< m, per keyframe, weights the scale estimate only
  double min_acceleration_rms = 0.2;     ///< m/s^2; 0 accepts still / constant-velocity starts
};

/// One keyframe as the visual odometry gives it: time and T_world_body (body = IMU frame), in
/// a metric but not gravity-aligned world (e.g. the first keyframe's body frame).
struct ImuInitKeyframe {
  double t = 0;
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();
};

struct ImuInitialization {
  bool success = false;
  /// Empty on success; otherwise every check that failed, with its numbers.
  std::string reason;
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();
  /// Gravity in the visual world, |gravity_world| = gravity_magnitude.
  Eigen::Vector3d gravity_world = Eigen::Vector3d::Zero();
  /// One per keyframe, in the visual world.
  std::vector<Eigen::Vector3d> velocities_world;
  /// R_gravity_world * gravity_world = (0, 0, -|g|); see rotationToGravityFrame.
  Eigen::Matrix3d R_gravity_world = Eigen::Matrix3d::Identity();
  double position_rms = 0;       ///< m, alignment residual after refinement
  double velocity_rms = 0;       ///< m/s, alignment residual after refinement
  double free_gravity_norm = 0;  ///< m/s^2, |g| before it is constrained to the sphere
  double acceleration_rms = 0;   ///< m/s^2, the excitation measure (file comment)
  /// Scale of the visual displacements as the IMU sees them (1 = consistent) and its standard
  /// error; NaN when the motion leaves it unobservable (file comment).
  double visual_scale = 0, visual_scale_sigma = 0;
};

/// Runs steps 1-3 on N >= 4 keyframes and the N - 1 preintegrations between consecutive ones
/// (preintegrations[k] from keyframes[k] to keyframes[k + 1], started at keyframes[k].t).
/// Once step 1 has run (every input check passed) the preintegrations are left repropagated at
/// the estimated gyro bias (their accelerometer-bias linearisation point kept), success or not:
/// the gyro bias does not depend on the acceleration checks. Never throws on bad data: it
/// returns success = false with the reason.
ImuInitialization initializeImu(const std::vector<ImuInitKeyframe>& keyframes,
                                const std::vector<ImuPreintegration*>& preintegrations,
                                const ImuInitializerOptions& options = {});

/// Step 1 alone: the gyro bias from the relative rotations, preintegrations repropagated at it.
/// Starts from preintegrations[0]->linearizedBg(). Zero, untouched, when the sizes do not
/// match (N keyframes, N - 1 >= 1 non-null preintegrations).
Eigen::Vector3d estimateGyroBias(const std::vector<ImuInitKeyframe>& keyframes,
                                 const std::vector<ImuPreintegration*>& preintegrations,
                                 int iterations);

/// The smallest rotation taking the direction of `gravity_world` to (0, 0, -1): its axis is
/// horizontal, so it changes no heading about gravity ("yaw left as is"). Not VINS's g2R, which
/// zeroes the yaw of a ZYX decomposition: the world here is the first body frame, whose x axis
/// may point up (EuRoC's IMU x does), where that yaw is undefined.
Eigen::Matrix3d rotationToGravityFrame(const Eigen::Vector3d& gravity_world);

}  // namespace dynslam::estimator
