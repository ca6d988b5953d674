#pragma once
// The sliding-window factor graph (method.md section 5): the last `window_size` keyframes'
// states, the static landmarks they observe, the IMU preintegration between consecutive
// keyframes (or, without an IMU, a constant-motion prior on the keyframe poses), and the prior
// left by marginalised keyframes. Each new keyframe: build the Ceres problem, solve it within
// the iteration and time limits, and when the window is full marginalise the oldest keyframe
// (Schur complement, Marginalizer) into the prior.
//
// Factors (one per file in factors/): StaticReprojectionFactor (Huber loss) and
// DepthMeasurementFactor / TransferredDepthFactor per static landmark, ImuFactor, the motion
// prior (RigidSmoothMotionFactor on the body poses), MarginalizationFactor, and per non-rigid
// feature NonRigidConstantVelocityFactor + NonRigidDepthFactor (r_D). A non-rigid point leaves
// the window with the keyframe it was first seen in (marginalised with it).
//
// Dynamic rigid objects (RigidObjectTable.h): per object one pose L per keyframe that sees it, one
// object-frame point m_obj per feature seen in two keyframes or more, RigidObjectReprojectionFactor
// (r_O, Huber) and RigidObjectDepthFactor per observation, RigidSmoothMotionFactor (r_om) over each
// three consecutive keyframes that all hold an L of the object.
// - Gauge: the object frame is free (L_n -> L_n G, m_obj -> G^-1 m_obj); the object's oldest L
//   in the problem is held constant, and before each solve the frame of every object seen in the
//   new keyframe is moved (axes kept) to the centroid of the points seen there. Why: the rigid set
//   on a walking person changes members, and an origin kept where the first members were drifted
//   off the torso over a window (docs/notes/estimator.md, 2026-11-28 (recentred)); recentred,
//   the object position written follows the points now seen, like the front-end's virtual
//   centroid.
// - Marginalisation: an object's factors touching the leaving keyframe are DROPPED, not put into
//   the prior, and its L there with them; the object's next L becomes its gauge. Why: objects
//   come and go (occlusions, people leaving the view), and a prior linking their states would
//   have to be carried, re-gauged and finally dropped anyway when the object leaves; the camera
//   loses only what r_om through the leaving keyframe said about it, which the static landmarks
//   and the IMU dominate. The non-rigid points, by contrast, go into the prior.
#include <dynslam/estimator/GnssAnchor.h>
#include <dynslam/estimator/ImuInitializer.h>
#include <dynslam/estimator/LandmarkTable.h>
#include <dynslam/estimator/RigidObjectTable.h>
#include <dynslam/estimator/factors/DepthMeasurementFactor.h>
#include <dynslam/estimator/factors/MarginalizationFactor.h>
#include <dynslam/estimator/factors/PinholeProjection.h>
#include <dynslam/estimator/imu/ImuPreintegration.h>

#include "dynslam/estimator/CalibrationExcitation.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace dynslam::estimator {

enum class ExtrinsicEstimation { None, Rotation, Full };

/// What becomes of a static landmark anchored at the keyframe that leaves the window; all its
/// factors went into the marginalisation prior with that keyframe. Next: anchored at its next
/// observation, its other observations in the window used again (VINS-Fusion), though the prior
/// already holds them. Newest: anchored at its newest observation, the ones before dropped, so
/// no measurement is counted twice (docs/notes/calibration.md, 2026-11-29 (later)).
enum class LandmarkReanchoring { Next, Newest };

/// Online camera-IMU calibration (VINS-Fusion's estimate_td and estimate_extrinsic): the time
/// offset t_d (t_imu = t_camera + t_d, StaticReprojectionFactor.h) and the extrinsic
/// T_body_camera become states of the window once it is visual-inertial, each held near its
/// configured value by a prior (CalibrationPriorFactor.h). Before the IMU initialization both
/// stay at their current values: without the IMU neither is observable.
struct CalibrationParams {
  bool estimate_time_offset = false;
  double time_offset_s = 0.0;  ///< the start value and the prior's mean (also when not estimated)
  double time_offset_sigma_s = 0.02;
  ExtrinsicEstimation estimate_extrinsic = ExtrinsicEstimation::None;
  double extrinsic_sigma_translation_m = 0.02;
  double extrinsic_sigma_rotation_deg = 3.0;
  /// Each estimated state is held (constant) while the window's motion does not observe it.
  ExcitationThresholds excitation;
};

/// What the window's calibration states hold, and their standard deviations (NaN when not
/// estimated, or when the covariance could not be had).
struct CalibrationEstimate {
  double time_offset_s = 0;
  double time_offset_sigma_s = std::numeric_limits<double>::quiet_NaN();
  Eigen::Isometry3d T_body_camera = Eigen::Isometry3d::Identity();
  /// Tangent [dp (m), dtheta (rad)] standard deviations of T_body_camera.
  Eigen::Matrix<double, 6, 1> extrinsic_sigma =
      Eigen::Matrix<double, 6, 1>::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// The [Estimator] keys among these: ranges and meanings in EstimatorOptions::describe()
/// (EstimatorOptions.cpp), docs/parameters.md.
struct SlidingWindowParams {
  int window_size = 10;
  /// Each solve starts from the last one's window, so few iterations are needed (measured:
  /// docs/notes/estimator.md, 2026-11-28 (max_iterations)).
  int max_iterations = 4;
  double max_solver_time_s = 0.05;
  /// Ceres runs its projected line search on any problem with bounds (ours: inverse depths
  /// >= 1e-3), and each of its steps evaluates the gradient again; with 0 a step is only
  /// projected onto the bounds, as accurate and faster (docs/notes/estimator.md, 2026-11-28
  /// (line_search_steps)).
  int line_search_steps = 0;
  double pixel_sigma = 1.0;
  double huber_sigmas = 2.0;
  DepthNoiseModel depth_noise;
  bool transferred_depth = true;
  LandmarkReanchoring landmark_reanchoring = LandmarkReanchoring::Next;
  bool use_imu = true;  ///< false: RGB-D only, motion prior between keyframes
  ImuNoise imu_noise;
  /// The world gravity the IMU factors start from (the window then holds it: gravity()).
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);
  double motion_prior_sigma_translation = 0.1, motion_prior_sigma_rotation = 0.05;
  /// > 0: while the window has no IMU factors but the keyframes carry preintegrations (IMU not
  /// yet initialized, or a restart), GyroRotationFactor between consecutive keyframes. Not the
  /// method (0); why and measured gain: docs/notes/estimator.md, 2026-11-28 (gyro_rotation_sigma).
  double gyro_rotation_sigma = 0.001;
  double object_motion_sigma_translation = 0.05, object_motion_sigma_rotation = 0.05;
  Eigen::Vector3d gnss_lever_arm = Eigen::Vector3d::Zero();
  double gnss_huber_sigmas = 3.0;
  CalibrationParams calibration;
};

struct FeatureObservation {
  std::int64_t id = -1;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double depth = 0;                                    ///< m; 0 = none
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< px/s (core::Feature::velocity)
};

/// One dynamic rigid object's features in a keyframe (r_O).
struct RigidObjectInput {
  int object_id = -1;
  std::vector<FeatureObservation> features;
  /// Where a new object's first pose L is put (the object frame the caller follows), else at
  /// the centroid of its measured points with the world's axes.
  std::optional<Eigen::Isometry3d> first_pose_guess;
};

struct KeyframeInput {
  double t = 0;
  Eigen::Isometry3d T_world_body = Eigen::Isometry3d::Identity();  ///< initial guess
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();              ///< initial guess (IMU)
  std::vector<FeatureObservation> features;                        ///< static features
  /// Features on dynamic non-rigid objects (method.md r_D): each a world point moving at
  /// constant velocity over the window; new ones need a measured depth.
  std::vector<FeatureObservation> nonrigid_features;
  /// Features on dynamic rigid objects (method.md r_O, r_om), per object.
  std::vector<RigidObjectInput> rigid_objects;
  /// The body's angular rate at the keyframe (rad/s, body frame; the last gyro sample), which
  /// with the window's velocity moves depths to the state time by the time offset.
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  /// IMU mode: the preintegration from the previous keyframe to this one (null for the first,
  /// and where the IMU stream had a gap: that pair is then linked by vision alone).
  std::shared_ptr<ImuPreintegration> preintegration;
};

struct SolveReport {
  int iterations = 0;
  double solve_ms = 0;
  int landmarks = 0;      ///< landmarks with factors in the problem
  int rigid_objects = 0;  ///< rigid objects with factors in the problem
  double final_cost = 0;
  bool usable = true;
  std::string message;  ///< Ceres' reason when not usable
};

class SlidingWindow {
 public:
  SlidingWindow(const SlidingWindowParams& params, const PinholeCamera& camera,
                const Eigen::Isometry3d& T_body_camera);
  ~SlidingWindow();

  /// Adds a keyframe (biases start from the previous keyframe's), solves, and marginalises the
  /// oldest keyframe when there are more than window_size.
  SolveReport addKeyframe(const KeyframeInput& input);

  bool empty() const { return keyframes_.empty(); }
  std::size_t size() const { return keyframes_.size(); }
  double latestTime() const;
  /// The static features each keyframe of the window was given (KeyframeInput::features),
  /// oldest first: they enter and leave with their keyframes.
  std::vector<std::size_t> featureCounts() const;
  Eigen::Isometry3d latestPose() const;
  Eigen::Vector3d latestVelocity() const;
  Eigen::Vector3d latestAccBias() const;
  Eigen::Vector3d latestGyroBias() const;

  /// The window's keyframes and the preintegrations between them (preintegrations[k] from
  /// keyframe k to k + 1), for initializeImu(). Empty when a preintegration is missing.
  bool imuInitInput(std::vector<ImuInitKeyframe>& keyframes,
                    std::vector<ImuPreintegration*>& preintegrations) const;

  /// Turns a window built from RGB-D alone into a visual-inertial one with the initializer's
  /// result: velocities and the gyro bias set, gravity taken as the initializer found it in
  /// this world (the world frame is not rotated: the trajectory written so far stays valid,
  /// also after a restart far from the origin), the IMU factors replace the motion prior. The
  /// marginalisation prior (made without the IMU) is dropped; the first keyframe then holds the
  /// gauge again.
  void switchToImu(const ImuInitialization& init);
  bool usesImu() const { return params_.use_imu; }
  /// The world gravity vector the IMU factors use: the IMU initialization's, re-estimated with
  /// the camera-IMU rotation while that is (gravityFree).
  Eigen::Vector3d gravity() const { return Eigen::Vector3d(gravity_); }

  /// The calibration states now (CalibrationParams): the extrinsic and time offset every factor
  /// uses. `with_sigma`: also their standard deviations from the last solve's problem (Ceres'
  /// covariance; costs about a solve).
  CalibrationEstimate calibration(bool with_sigma = false);
  Eigen::Isometry3d extrinsic() const;
  /// The configured T_body_camera the window started from (the extrinsic prior's mean).
  const Eigen::Isometry3d& extrinsicPrior() const { return extrinsic_prior_; }
  double timeOffset() const { return time_offset_[0]; }
  /// Whether the last solve's motion (CalibrationExcitation.h) freed each estimated calibration
  /// state (false when not estimated).
  bool timeOffsetFree() const;
  bool extrinsicFree() const;
  /// The initialization found the world gravity through the configured camera-IMU rotation:
  /// when that rotation is estimated, a gravity held fixed would keep its error, and the camera's
  /// poses would turn by the rotation's correction (2 deg on indoor_people_high,
  /// docs/notes/calibration.md). So the two are estimated together.
  bool gravityFree() const { return extrinsicFree(); }
  /// A restarted window goes on from the last window's calibration (the priors keep their
  /// configured means).
  void continueCalibration(const Eigen::Isometry3d& T_body_camera, double time_offset_s);
  /// A pixel moved to its keyframe's state time by the current time offset.
  Eigen::Vector2d atStateTime(const Eigen::Vector2d& pixel, const Eigen::Vector2d& velocity) const {
    return pixel - time_offset_[0] * velocity;
  }

  /// The world velocity of non-rigid feature `id` when the window estimates it (seen in two
  /// keyframes or more), else nothing.
  std::optional<Eigen::Vector3d> nonRigidVelocity(std::int64_t id) const;

  /// The rigid objects' poses L = T_world_object at the newest keyframe: the solve's estimate
  /// (an L without factors yet keeps its initial value).
  std::vector<std::pair<int, Eigen::Isometry3d>> latestObjectPoses() const;

  /// Deletes these features' static landmarks (all their observations) from the window, e.g.
  /// once they are classified as moving; returns how many there were. The prior keeps what
  /// earlier marginalisations took from them.
  std::size_t dropLandmarks(const std::vector<std::int64_t>& ids);

  /// World positions of the landmarks seen in at least two keyframes, for tracking frames
  /// between keyframes.
  std::vector<std::pair<std::int64_t, Eigen::Vector3d>> landmarkPositions() const;

  /// The GNSS antenna's world position at the keyframe of time `t` (gnss_lever_arm on its pose),
  /// nothing when no keyframe of the window has that time.
  std::optional<Eigen::Vector3d> antennaAt(double t) const;
  /// Puts a GNSS position factor on the keyframe of time target.t from the next solve on (it is
  /// marginalised into the prior with that keyframe). False when the keyframe has left.
  bool addGnssTarget(const GnssTarget& target);

 private:
  struct Keyframe {
    std::int64_t id = 0;
    double t = 0;
    std::size_t features = 0;  // static features given to it
    double pose[7];
    double speed_bias[9];
    Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // body, rad/s
    std::shared_ptr<ImuPreintegration> preintegration;           // from the previous keyframe
    std::optional<GnssTarget> gnss;  // GnssPositionFactor on the pose when set
  };
  /// A non-rigid feature: world position at its first keyframe's time t0 and world velocity.
  struct NonRigidPoint {
    double t0 = 0;
    double position[3];
    double velocity[3];
    std::map<std::int64_t, LandmarkObservation> observations;  // by keyframe id
  };
  struct Prior {
    std::shared_ptr<MarginalizationFactor> factor;
    std::vector<double*> blocks;
  };
  class ProblemBuilder;

  SolveReport solve();  // SlidingWindowProblem.cpp
  /// The keyframe's non-rigid observations: new points placed by their depth.
  void observeNonRigid(const KeyframeInput& input, const Keyframe& k);
  bool calibrationSettling() const;
  bool estimatesTimeOffset() const;
  bool estimatesExtrinsic() const;
  /// excitation_ from the keyframes' current states, before a solve.
  void updateExcitation();
  void repropagatePreintegrations();
  void marginalizeOldest();
  Eigen::Vector3d landmarkWorld(const Landmark& l) const;
  /// A static point's depth measured at `pixel` (already at the state time) in keyframe `k`,
  /// moved back to the state time: the image was taken t_d later, while the camera moved with
  /// the keyframe's velocity and angular rate (the current estimate, constant within a solve).
  double depthAtStateTime(const Keyframe& k, const Eigen::Vector2d& pixel, double depth) const;
  /// Depth of a world point in keyframe `k`'s camera, at the current estimate.
  double depthIn(const Keyframe& k, const Eigen::Vector3d& world) const;
  Keyframe* keyframe(std::int64_t id);
  const Keyframe* keyframe(std::int64_t id) const;
  /// The keyframe stamped `t` (the time the caller gave it), null when it has left the window.
  Keyframe* keyframeAt(double t);

  SlidingWindowParams params_;
  PinholeCamera camera_;
  double extrinsic_[7];
  double time_offset_[1];
  double gravity_[3];  // the world gravity vector (ImuFactor's fifth block)
  // The first keyframe's camera pose holding the gauge while the extrinsic is estimated and
  // there is no prior yet (CameraPosePriorFactor.h); marginalised with that keyframe.
  std::optional<Eigen::Isometry3d> camera_anchor_;
  CalibrationExcitation excitation_;
  int imu_keyframes_ = 0;              // keyframes added since the window turned visual-inertial
  Eigen::Isometry3d extrinsic_prior_;  // the configured T_body_camera, the prior's mean
  std::deque<Keyframe> keyframes_;
  std::int64_t next_id_ = 0;
  LandmarkTable landmarks_;
  std::map<std::int64_t, NonRigidPoint> nonrigid_;
  RigidObjectTable objects_;
  Prior prior_;
};

}  // namespace dynslam::estimator
