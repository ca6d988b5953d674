// SlidingWindow on a synthetic scene: static points on a shell around an analytic body motion,
// seen by a camera on the body. RGB-D only and with the IMU, from perturbed initial guesses, the
// window (5 keyframes, so marginalisation runs many times) tracks the true poses.
#include "ImuTestMotion.h"

#include <dynslam/estimator/SlidingWindow.h>

#include <gtest/gtest.h>

#include <random>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

struct Scene {
  std::vector<Eigen::Vector3d> points;
  PinholeCamera camera{500, 500, 320, 240};
  Eigen::Isometry3d T_body_camera = Eigen::Isometry3d::Identity();

  Scene() {
    std::mt19937 rng(11);
    std::normal_distribution<double> n(0, 1);
    std::uniform_real_distribution<double> r(4, 6);
    for (int i = 0; i < 600; ++i) {
      const Eigen::Vector3d d = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
      points.push_back(d * r(rng));
    }
    T_body_camera.linear() = quaternionExp(Eigen::Vector3d(-1.2, 0.1, 0.05)).toRotationMatrix();
    T_body_camera.translation() = Eigen::Vector3d(0.05, -0.02, 0.01);
  }

  Eigen::Isometry3d bodyAt(double t) const {
    const MotionState m = motionAt(t);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = m.q.toRotationMatrix();
    T.translation() = m.p;
    return T;
  }

  std::vector<FeatureObservation> observe(double t, std::mt19937& rng, double pixelNoise) const {
    std::normal_distribution<double> n(0, pixelNoise);
    const Eigen::Isometry3d T_cw = (bodyAt(t) * T_body_camera).inverse();
    std::vector<FeatureObservation> out;
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d p = T_cw * points[i];
      if (p.z() < 0.5) continue;
      const Eigen::Vector2d px = camera.project(p);
      if (px.x() < 0 || px.y() < 0 || px.x() >= 640 || px.y() >= 480) continue;
      out.push_back({std::int64_t(i), px + Eigen::Vector2d(n(rng), n(rng)), p.z()});
    }
    return out;
  }

  /// A walker's points, given in the first camera's frame (at t = 1 s) and moving with `walk`
  /// (m/s, world), seen at time t: ids firstId + i, exact pixels and depths.
  std::vector<FeatureObservation> observeWalker(const std::vector<Eigen::Vector3d>& walker,
                                                const Eigen::Vector3d& walk, double t,
                                                std::int64_t firstId) const {
    const Eigen::Isometry3d T_wc0 = bodyAt(1.0) * T_body_camera;
    const Eigen::Isometry3d T_cw = (bodyAt(t) * T_body_camera).inverse();
    std::vector<FeatureObservation> out;
    for (size_t i = 0; i < walker.size(); ++i) {
      const Eigen::Vector3d p = T_cw * (T_wc0 * walker[i] + walk * (t - 1.0));
      if (p.z() >= 0.5) out.push_back({firstId + std::int64_t(i), camera.project(p), p.z()});
    }
    return out;
  }
};

std::shared_ptr<ImuPreintegration> preintegrate(double t0, double t1) {
  const double dt = 0.005;
  auto pre = std::make_shared<ImuPreintegration>(specificForce(t0), bodyRate(),
                                                 Eigen::Vector3d::Zero(),
                                                 Eigen::Vector3d::Zero(), ImuNoise{});
  for (int k = 1; k <= int(std::lround((t1 - t0) / dt)); ++k)
    pre->push(dt, specificForce(t0 + k * dt), bodyRate());
  return pre;
}

/// A 5-keyframe window (marginalisation runs many times) on the test motion's gravity, as the
/// method has it: without an IMU no gyro factor (gyro_rotation_sigma 0). Its solves stop at
/// their iteration limit, not on the clock: under load a 50 ms limit cut them short.
SlidingWindowParams fiveKeyframes(bool useImu) {
  SlidingWindowParams params;
  params.window_size = 5;
  params.max_solver_time_s = 100;
  params.gyro_rotation_sigma = 0;
  params.use_imu = useImu;
  params.gravity = kTestGravity;
  return params;
}

double run(bool useImu, double pixelNoise, double* velocityError = nullptr,
           int lineSearchSteps = SlidingWindowParams{}.line_search_steps) {
  Scene scene;
  SlidingWindowParams params = fiveKeyframes(useImu);
  params.line_search_steps = lineSearchSteps;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  std::mt19937 rng(2);
  double worst = 0;
  const double step = 0.1;
  for (int k = 0; k < 20; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, pixelNoise);
    // Initial guess: the truth for the first keyframe (it fixes the gauge), else the previous
    // estimate moved by the true motion plus a 3 cm / 1 deg error.
    Eigen::Isometry3d guess = scene.bodyAt(t);
    if (k > 0) {
      guess = window.latestPose() * scene.bodyAt(t - step).inverse() * scene.bodyAt(t);
      guess.translation() += Eigen::Vector3d(0.03, -0.02, 0.01);
      guess.linear() = guess.linear() * quaternionExp(Eigen::Vector3d(0.017, 0, 0)).toRotationMatrix();
      in.preintegration = preintegrate(t - step, t);
    }
    in.T_world_body = guess;
    in.velocity = motionAt(t).v + (k > 0 ? Eigen::Vector3d(0.05, 0, 0) : Eigen::Vector3d::Zero());
    const SolveReport report = window.addKeyframe(in);
    EXPECT_TRUE(report.usable);
    EXPECT_LE(window.size(), 5u);
    if (k >= 2) {
      const double error = (window.latestPose().translation() - scene.bodyAt(t).translation()).norm();
      worst = std::max(worst, error);
      if (velocityError) *velocityError = (window.latestVelocity() - motionAt(t).v).norm();
    }
  }
  return worst;
}

/// The velocity error (m/s) of keyframe 10 after its solve, when it came without a
/// preintegration (an IMU gap) and with the velocity the stage then predicts: zero. No IMU factor
/// reaches it until the next keyframe, and the stage propagates the IMU from this velocity to
/// predict the frames until then.
double velocityErrorAfterAnImuGap() {
  Scene scene;
  SlidingWindow window(fiveKeyframes(true), scene.camera, scene.T_body_camera);
  std::mt19937 rng(2);
  const double step = 0.1;
  double error = -1;
  for (int k = 0; k <= 10; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, 0.0);
    in.T_world_body = scene.bodyAt(t);
    in.velocity = k == 10 ? Eigen::Vector3d::Zero() : motionAt(t).v;
    if (k > 0 && k != 10) in.preintegration = preintegrate(t - step, t);
    window.addKeyframe(in);
    if (k == 10) error = (window.latestVelocity() - motionAt(t).v).norm();
  }
  return error;
}

/// Worst rotation error (deg) of the newest keyframe over 2 s, RGB-D only, when a crowd taken for
/// static (600 points 2-3 m round the camera, as many as the scene's static ones) turns about it
/// at 0.5 rad/s, with the keyframes' gyro preintegrations and the given gyro_rotation_sigma.
double rotationErrorAmongATurningCrowd(double gyroSigma) {
  Scene scene;
  SlidingWindowParams params = fiveKeyframes(false);
  params.gyro_rotation_sigma = gyroSigma;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  const Eigen::Vector3d centre = scene.bodyAt(1.0).translation();
  std::vector<Eigen::Vector3d> crowd;
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> r(2, 3);
  for (int i = 0; i < 600; ++i)
    crowd.push_back(centre + Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized() * r(rng));
  double worst = 0;
  const double step = 0.1;
  for (int k = 0; k < 20; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, 0.3);
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.5 * (t - 1.0), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Isometry3d T_cw = (scene.bodyAt(t) * scene.T_body_camera).inverse();
    for (size_t i = 0; i < crowd.size(); ++i) {
      const Eigen::Vector3d p = T_cw * (centre + turn * (crowd[i] - centre));
      const Eigen::Vector2d px = scene.camera.project(p);
      if (p.z() > 0.5 && px.x() >= 0 && px.y() >= 0 && px.x() < 640 && px.y() < 480)
        in.features.push_back({100000 + std::int64_t(i), px, p.z()});
    }
    in.T_world_body = scene.bodyAt(t);
    if (k > 0) {
      in.T_world_body = window.latestPose() * scene.bodyAt(t - step).inverse() * scene.bodyAt(t);
      in.preintegration = preintegrate(t - step, t);
    }
    window.addKeyframe(in);
    const Eigen::AngleAxisd error(window.latestPose().rotation().transpose() *
                                  scene.bodyAt(t).rotation());
    worst = std::max(worst, std::abs(error.angle()) * 180 / M_PI);
  }
  return worst;
}

}  // namespace

TEST(SlidingWindow, TheGyroKeepsTheRotationWhenACrowdTurnsRoundTheCameraBeforeImuInit) {
  const double without = rotationErrorAmongATurningCrowd(0.0);
  const double with = rotationErrorAmongATurningCrowd(0.001);
  std::printf("worst rotation error over 2 s: %.2f deg without the gyro factor, %.2f with\n",
              without, with);
  EXPECT_GT(without, 10.0) << "the crowd must turn the window for this test to mean anything";
  EXPECT_LT(with, 2.5);
}

TEST(SlidingWindow, AKeyframeAfterAnImuGapStartsFromItsMeanVelocity) {
  // Started from zero the velocity stays 0.53 m/s off; the mean over the 0.1 s interval before
  // differs from the velocity at its end by the motion's acceleration over half of it (0.06).
  EXPECT_LT(velocityErrorAfterAnImuGap(), 0.1) << "m/s, the keyframe after the gap";
}

TEST(SlidingWindow, RgbdOnlyTracksTheTruePosesThroughMarginalisation) {
  EXPECT_LT(run(false, 0.0), 0.002) << "exact pixels: worst position error of the newest keyframe, m";
  EXPECT_LT(run(false, 0.5), 0.03) << "0.5 px noise: odometry drift over 2 s, m";
}

TEST(SlidingWindow, WithImuTracksPosesAndVelocity) {
  double velocityError = 1;
  EXPECT_LT(run(true, 0.0, &velocityError), 0.002) << "exact pixels, m";
  EXPECT_LT(velocityError, 0.005) << "last velocity error, m/s";
  EXPECT_LT(run(true, 0.5, &velocityError), 0.02) << "0.5 px noise, m";
  EXPECT_LT(velocityError, 0.05) << "last velocity error, m/s";
}

// The default leaves out Ceres's projected line search (a third of the solve time on the
// simulator); the window must track as it does with Ceres's own default of 20 steps.
TEST(SlidingWindow, StepsOnlyProjectedOntoTheBoundsTrackAsWellAsWithCeresLineSearch) {
  ASSERT_EQ(SlidingWindowParams{}.line_search_steps, 0);
  for (const bool useImu : {false, true}) {
    const double without = run(useImu, 0.5, nullptr, 0);
    const double with = run(useImu, 0.5, nullptr, 20);
    std::printf("%s, 0.5 px: worst position error %.4f m without the line search, %.4f with\n",
                useImu ? "with IMU" : "RGB-D only", without, with);
    EXPECT_LT(without, useImu ? 0.02 : 0.03);
    EXPECT_LT(without, with + 0.002) << "no worse than with Ceres's line search, m";
  }
}

TEST(SlidingWindow, NonRigidPointsGetTheirVelocity) {
  // Static shell plus 12 points of a walker 3 m in front of the camera's start, moving at a
  // constant 0.8 m/s; RGB-D + IMU, exact pixels and depths.
  Scene scene;
  SlidingWindowParams params;
  params.window_size = 5;
  params.gravity = kTestGravity;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  const Eigen::Vector3d walk(0.8, 0.0, 0.0);
  std::vector<Eigen::Vector3d> walker;
  for (int i = 0; i < 12; ++i) walker.push_back(Eigen::Vector3d(0.2 * (i % 4), 0.3 * (i / 4), 3));
  std::mt19937 rng(4);
  const double step = 0.1;
  int checked = 0;
  for (int k = 0; k < 12; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, 0.0);
    in.T_world_body = scene.bodyAt(t);
    in.velocity = motionAt(t).v;
    if (k > 0) in.preintegration = preintegrate(t - step, t);
    in.nonrigid_features = scene.observeWalker(walker, walk, t, 10000);
    ASSERT_TRUE(window.addKeyframe(in).usable);
    if (k < 3) continue;
    for (size_t i = 0; i < walker.size(); ++i)
      if (const auto v = window.nonRigidVelocity(std::int64_t(10000 + i))) {
        EXPECT_LT((*v - walk).norm(), 0.05) << "point " << i << " keyframe " << k;
        ++checked;
      }
  }
  EXPECT_GT(checked, 20) << "non-rigid points estimated";
}

namespace {

/// A rigid box of 16 points 3 m in front of the first camera, moving by the same object-frame
/// motion H (8 cm along its x and 0.05 rad about its z) every keyframe interval: r_om's model.
struct MovingBox {
  std::vector<Eigen::Vector3d> points;  // object frame
  Eigen::Isometry3d L0 = Eigen::Isometry3d::Identity(), H = Eigen::Isometry3d::Identity();

  explicit MovingBox(const Eigen::Isometry3d& T_world_camera0) {
    // A 4 x 4 grid, its z alternating +-0.15 m as a checkerboard.
    for (int i = 0; i < 16; ++i)
      points.push_back(Eigen::Vector3d(0.3 * (i % 4) - 0.45, 0.3 * (i / 4) - 0.45,
                                       (i % 4 + i / 4) % 2 ? 0.15 : -0.15));
    L0 = T_world_camera0;
    L0.translation() = T_world_camera0 * Eigen::Vector3d(0, 0, 3);
    H.linear() = quaternionExp(Eigen::Vector3d(0, 0, 0.05)).toRotationMatrix();
    H.translation() = Eigen::Vector3d(0.08, 0, 0);
  }

  Eigen::Isometry3d poseAt(int k) const {
    Eigen::Isometry3d L = L0;
    for (int i = 0; i < k; ++i) L = L * H;
    return L;
  }
};

struct RigidRunResult {
  double camera_worst = 0;  ///< m, newest keyframe's position error, worst over the run
  double object_worst_translation = 0, object_worst_rotation_deg = 0;
  int object_poses_checked = 0;
  bool all_finite = true;
};

/// RGB-D only, 0.5 px noise, perturbed initial guesses as run(); the box's features given to
/// the window as a rigid object (withObject) or not at all.
RigidRunResult runWithMovingBox(bool withObject) {
  Scene scene;
  SlidingWindowParams params;
  params.window_size = 5;
  params.use_imu = false;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  const MovingBox box(scene.bodyAt(1.0) * scene.T_body_camera);
  std::mt19937 rng(5);
  std::normal_distribution<double> pixelNoise(0, 0.5);
  RigidRunResult result;
  const double step = 0.1;
  for (int k = 0; k < 14; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, 0.5);
    Eigen::Isometry3d guess = scene.bodyAt(t);
    if (k > 0) {
      guess = window.latestPose() * scene.bodyAt(t - step).inverse() * scene.bodyAt(t);
      guess.translation() += Eigen::Vector3d(0.03, -0.02, 0.01);
    }
    in.T_world_body = guess;
    const Eigen::Isometry3d L = box.poseAt(k);
    const Eigen::Isometry3d T_cw = (scene.bodyAt(t) * scene.T_body_camera).inverse();
    RigidObjectInput object;
    object.object_id = 7;
    object.first_pose_guess = box.L0;  // the object frame the test compares in
    for (size_t i = 0; i < box.points.size(); ++i) {
      const Eigen::Vector3d p = T_cw * (L * box.points[i]);
      if (p.z() < 0.5) continue;
      const Eigen::Vector2d noise(pixelNoise(rng), pixelNoise(rng));
      object.features.push_back({std::int64_t(20000 + i), scene.camera.project(p) + noise, p.z()});
    }
    if (withObject) in.rigid_objects.push_back(object);
    const SolveReport report = window.addKeyframe(in);
    result.all_finite =
        result.all_finite && report.usable && window.latestPose().matrix().allFinite();
    if (k < 2) continue;
    result.camera_worst =
        std::max(result.camera_worst,
                 (window.latestPose().translation() - scene.bodyAt(t).translation()).norm());
    for (const auto& [id, estimate] : window.latestObjectPoses()) {
      result.all_finite = result.all_finite && estimate.matrix().allFinite();
      // The window's object frame: the truth's axes, its origin at the centroid of the points
      // seen now.
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const auto& f : object.features) centroid += box.points[size_t(f.id - 20000)];
      Eigen::Isometry3d truth = L;
      truth.translation() = L * (centroid / double(object.features.size()));
      const Eigen::Isometry3d error = truth.inverse() * estimate;
      result.object_worst_translation =
          std::max(result.object_worst_translation, error.translation().norm());
      result.object_worst_rotation_deg =
          std::max(result.object_worst_rotation_deg,
                   Eigen::AngleAxisd(error.rotation()).angle() * 180 / M_PI);
      ++result.object_poses_checked;
    }
  }
  return result;
}

}  // namespace

TEST(SlidingWindow, RigidObjectPosesFollowTheMovingObjectThroughMarginalisation) {
  const RigidRunResult with = runWithMovingBox(true), without = runWithMovingBox(false);
  EXPECT_TRUE(with.all_finite);
  EXPECT_GE(with.object_poses_checked, 10) << "object poses estimated at the newest keyframe";
  EXPECT_LT(with.object_worst_translation, 0.03) << "m, worst object position error";
  EXPECT_LT(with.object_worst_rotation_deg, 1.0) << "deg, worst object rotation error";
  // The object's factors must not pull the camera: its error at most that without them (2 mm
  // slack for the different random draws the solve sees).
  EXPECT_LT(with.camera_worst, without.camera_worst + 0.002)
      << "with " << with.camera_worst << " m, without " << without.camera_worst << " m";
  EXPECT_LT(with.camera_worst, 0.03);
}

namespace {

/// RGB-D only, exact pixels: a walker of 150 points 2 m in front of the first camera, moving at
/// 0.8 m/s, passes for static in keyframes 4-7 (it entered the view undetected). From keyframe 8
/// on it is known to move: its features are no longer given, and with `dropWhenMoving` its
/// landmarks leave the window. Returns the worst position error of the newest keyframe over
/// keyframes 8-13.
double walkerTakenForStatic(bool dropWhenMoving) {
  Scene scene;
  SlidingWindowParams params;
  params.window_size = 8;
  params.use_imu = false;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  std::vector<Eigen::Vector3d> walker;  // first camera's frame
  for (int i = 0; i < 150; ++i) walker.push_back(Eigen::Vector3d(u(rng), 2 * u(rng), 2 + u(rng)));
  std::vector<std::int64_t> walkerIds;
  for (size_t i = 0; i < walker.size(); ++i) walkerIds.push_back(std::int64_t(100000 + i));
  const Eigen::Vector3d walk(0.8, 0.0, 0.0);
  const double step = 0.1;
  double worst = 0;
  for (int k = 0; k < 14; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, 0.0);
    in.T_world_body =
        k == 0 ? scene.bodyAt(t)
               : window.latestPose() * scene.bodyAt(t - step).inverse() * scene.bodyAt(t);
    if (k >= 4 && k <= 7) {
      const auto seen = scene.observeWalker(walker, walk, t, 100000);
      in.features.insert(in.features.end(), seen.begin(), seen.end());
    }
    if (k == 8 && dropWhenMoving) {
      EXPECT_GT(window.dropLandmarks(walkerIds), 100u);
    }
    EXPECT_TRUE(window.addKeyframe(in).usable);
    if (k >= 8)
      worst = std::max(worst,
                       (window.latestPose().translation() - scene.bodyAt(t).translation()).norm());
  }
  return worst;
}

}  // namespace

TEST(SlidingWindow, LandmarksOfAWalkerTakenForStaticLeaveWhenItIsKnownToMove) {
  const double kept = walkerTakenForStatic(false);
  const double dropped = walkerTakenForStatic(true);
  EXPECT_LT(dropped, 0.01) << "m; the walker kept: " << kept << " m";
  EXPECT_GT(kept, 3 * dropped) << "m; the walker's landmarks moved the window";
}

namespace {

/// The scale of 10 s of RGB-D-only keyframes (10-keyframe window): the mean length of the chords
/// 2 s apart, estimate over truth, minus 1. Pixels get Gaussian noise of `pixelNoise` px, depths
/// `depthNoise` * z^2 m (the model the estimator assumes is 0.001 + 0.0015 z^2).
double scaleError(bool transferredDepth, double pixelNoise, double depthNoise, unsigned seed = 2) {
  Scene scene;
  SlidingWindowParams params = fiveKeyframes(false);
  params.window_size = 10;
  params.transferred_depth = transferredDepth;
  SlidingWindow window(params, scene.camera, scene.T_body_camera);
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0, 1);
  const double step = 0.1;
  std::vector<Eigen::Vector3d> truth, estimate;
  for (int k = 0; k < 100; ++k) {
    const double t = 1.0 + k * step;
    KeyframeInput in;
    in.t = t;
    in.features = scene.observe(t, rng, pixelNoise);
    for (auto& f : in.features) f.depth += depthNoise * f.depth * f.depth * unit(rng);
    in.T_world_body =
        k == 0 ? scene.bodyAt(t)
               : window.latestPose() * scene.bodyAt(t - step).inverse() * scene.bodyAt(t);
    window.addKeyframe(in);
    estimate.push_back(window.latestPose().translation());
    truth.push_back(scene.bodyAt(t).translation());
  }
  double lengthTrue = 0, lengthEstimated = 0;
  for (size_t k = 0; k + 20 < truth.size(); ++k) {
    lengthTrue += (truth[k + 20] - truth[k]).norm();
    lengthEstimated += (estimate[k + 20] - estimate[k]).norm();
  }
  return lengthEstimated / lengthTrue - 1;
}

}  // namespace

// Exact pixels and depths: the window keeps the scale (a formulation error would show here).
// With noise, the depth measured in later keyframes (transferred_depth, the default) keeps it
// too on average; without it the depth at the first observation alone leaves the scale to the
// noise. The means over seeds 1-4 are printed (docs/notes/estimator.md, 2026-11-28
// (transferred_depth and the scale)).
TEST(SlidingWindow, KeepsTheScaleOnExactDataAndOnAverageUnderNoise) {
  EXPECT_LT(std::abs(scaleError(true, 0.0, 0.0)), 1e-4);
  EXPECT_LT(std::abs(scaleError(false, 0.0, 0.0)), 1e-4);
  for (const auto& [pixel, depth] : {std::pair{1.0, 0.0}, std::pair{0.0, 0.003}}) {
    double mean = 0, meanWithout = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
      mean += scaleError(true, pixel, depth, seed) / 4;
      meanWithout += scaleError(false, pixel, depth, seed) / 4;  // printed
    }
    std::printf(
        "%.1f px, depth %.3f z^2: mean scale error %+.3f %% with transferred_depth, "
        "%+.3f %% without\n",
        pixel, depth, 100 * mean, 100 * meanWithout);
    EXPECT_LT(std::abs(mean), 0.005) << pixel << " px, depth noise " << depth << " z^2";
  }
}

TEST(SlidingWindow, CountsEachKeyframesFeaturesUntilItLeaves) {
  Scene scene;
  SlidingWindow window(fiveKeyframes(false), scene.camera, scene.T_body_camera);
  std::mt19937 rng(2);
  std::vector<std::size_t> given;
  for (int k = 0; k < 8; ++k) {
    const double t = 1.0 + 0.1 * k;
    KeyframeInput in;
    in.t = t;
    in.T_world_body = scene.bodyAt(t);
    in.features = scene.observe(t, rng, 0.0);
    if (k == 1) in.features.clear();  // a black frame
    if (k == 2) in.features.resize(7);
    given.push_back(in.features.size());
    window.addKeyframe(in);
    const std::size_t first = given.size() > 5 ? given.size() - 5 : 0;
    EXPECT_EQ(window.featureCounts(),
              std::vector<std::size_t>(given.begin() + long(first), given.end()));
  }
}
