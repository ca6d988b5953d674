// The camera-IMU calibration the estimator is configured with (CalibrationParams in
// SlidingWindow.h, camera_in_imu) on synthetic frames (SyntheticFrames.h) whose images are taken
// late: a known offset corrects them; bad values are refused naming their key.
#include "StageTestSupport.h"
#include "SyntheticFrames.h"

#include <dynslam/estimator/EstimatorStage.h>
#include <dynslam/estimator/StateBlocks.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

using namespace dynslam;
using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// camera_in_imu for the identity turned by `degrees` about `axis`.
std::string rotatedCamera(double degrees, const Eigen::Vector3d& axis) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()).matrix();
  std::string out = "camera_in_imu =";
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      out += " " + std::to_string(r < 3 && c < 3 ? R(r, c) : (r == c ? 1.0 : 0.0));
  return out + "\n";
}

}  // namespace

// A time offset known beforehand (configured, not estimated) moves every feature back to its
// state's time: on images taken 30 ms after their stamps the poses lose the lag.
TEST(OnlineCalibration, AKnownTimeOffsetTakesTheLagOutOfThePoses) {
  double rms[2] = {0, 0};
  for (const int corrected : {0, 1}) {
    SyntheticFramesOptions options;
    options.time_offset = 0.03;
    SyntheticFrames source(options);
    auto stage = makeStage(corrected ? "time_offset = 0.03\n" : "");
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; source.time(i) <= 6; ++i) {
      core::Frame f = source.frame(i);
      stage->process(f);
      ASSERT_TRUE(f.T_world_camera.has_value());
      if (f.index < 60) continue;  // after the IMU initialization
      sum += (f.T_world_camera->translation() - source.truth(i).translation()).squaredNorm();
      ++n;
    }
    rms[corrected] = std::sqrt(sum / n);
  }
  std::printf("images 30 ms late: position RMS %.2f mm as stamped, %.2f mm with time_offset\n",
              1e3 * rms[0], 1e3 * rms[1]);
  EXPECT_LT(rms[1], 0.003);
  EXPECT_LT(rms[1], 0.25 * rms[0]);
}

TEST(OnlineCalibration, ABadTimeOffsetPriorOrExtrinsicIsRefusedNamingTheKey) {
  EXPECT_NE(configRefusal("time_offset = 0.25\n").find("time_offset"), std::string::npos);
  EXPECT_NE(configRefusal("time_offset = -0.21\n").find("time_offset"), std::string::npos);
  EXPECT_EQ(configRefusal("time_offset = 0.2\n"), "");
  // A scaled rotation, a reflection, a matrix too short, a bottom row that is not 0 0 0 1.
  const std::string scaled = "camera_in_imu = 1.01 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n";
  const std::string reflected = "camera_in_imu = -1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n";
  const std::string shortOne = "camera_in_imu = 1 0 0 0  0 1 0 0  0 0 1 0\n";
  const std::string bottom = "camera_in_imu = 1 0 0 0  0 1 0 0  0 0 1 0  0 0 1 1\n";
  for (const auto& bad : {scaled, reflected, shortOne, bottom}) {
    const std::string why = configRefusal(bad);
    EXPECT_NE(why.find("[Estimator] camera_in_imu"), std::string::npos) << bad << " -> " << why;
  }
  EXPECT_NE(configRefusal(scaled).find("orthonormal"), std::string::npos);
  EXPECT_EQ(configRefusal(rotatedCamera(2.0, Eigen::Vector3d::UnitZ())), "");
}

namespace {

/// The calibration's drift over 10 s of SyntheticFrames' straight line at constant velocity
/// without rotation (from 5 s, when the window's keyframes are all past the start's swing, to
/// 15 s), images 20 ms late, the believed extrinsic turned 2 deg: t_d's change (ms), the
/// extrinsic's rotation (deg), and the keyframes of those 10 s that estimated either.
struct Drift {
  double time_offset_ms = 0, rotation_deg = 0;
  int free_keyframes = 0;
};

Drift driftOnAStraightLine(const std::string& extra) {
  SyntheticFramesOptions options;
  options.straight = true;
  options.time_offset = 0.02;
  SyntheticFrames source(options);
  auto stage = makeStage("estimate_time_offset = true\nestimate_extrinsic = rotation\n" +
                         rotatedCamera(2.0, Eigen::Vector3d(1, 2, 3)) + extra);
  constexpr double kFrom = 5, kTo = 15;
  std::optional<core::KeyframeRecord> first, last;
  Drift out;
  for (std::size_t i = 0; source.time(i) <= kTo; ++i) {
    core::Frame f = source.frame(i);
    stage->process(f);
    if (!f.keyframe || f.t < kFrom) continue;
    EXPECT_TRUE(f.keyframe->visual_inertial) << "at " << f.t << " s";
    if (!first) first = f.keyframe;
    last = f.keyframe;
    out.free_keyframes += f.keyframe->time_offset_free + f.keyframe->extrinsic_free;
  }
  if (!first) return out;
  out.time_offset_ms = 1e3 * (last->time_offset - first->time_offset);
  const Eigen::Quaterniond from = quaternionExp(first->extrinsic_rotation_change);
  const Eigen::Quaterniond to = quaternionExp(last->extrinsic_rotation_change);
  out.rotation_deg = from.angularDistance(to) * 180 / M_PI;
  return out;
}

}  // namespace

// Constant velocity without rotation observes neither the time offset nor the extrinsic
// (CalibrationExcitation.h): both stay where they are instead of following the noise.
TEST(OnlineCalibration, MotionThatDoesNotObserveTheCalibrationKeepsItWhereItIs) {
  const Drift held = driftOnAStraightLine("");
  const Drift free = driftOnAStraightLine(
      "calibration_min_rotation_deg = 0\ncalibration_min_rate_change = 0\n"
      "calibration_min_velocity_change = 0\n");
  std::printf(
      "straight line, no rotation, 10 s: t_d moved %.3f ms, the extrinsic %.4f deg "
      "(%d keyframes free); never held: %.3f ms, %.4f deg\n",
      held.time_offset_ms, held.rotation_deg, held.free_keyframes, free.time_offset_ms,
      free.rotation_deg);
  EXPECT_EQ(held.free_keyframes, 0);
  EXPECT_LT(std::abs(held.time_offset_ms), 0.1);
  EXPECT_LT(held.rotation_deg, 0.02);
  // What the hold prevents: left free, the extrinsic follows the noise.
  EXPECT_GT(free.free_keyframes, 0);
  EXPECT_GT(free.rotation_deg, 0.05);
}

// A believed camera-IMU rotation 2 deg off, estimated along the room path: the rotation is
// recovered, and the camera's orientation stays right while it is (the world gravity the IMU
// initialization found through the wrong rotation is estimated with it; held, the camera turned
// by the correction, docs/notes/calibration.md).
TEST(OnlineCalibration, AWrongExtrinsicRotationIsRecoveredWithoutTurningTheCamera) {
  SyntheticFrames source{SyntheticFramesOptions{}};
  // About an axis square to the path's rotation axis and to gravity: a turn about either is not
  // observable on a path that rotates about one axis only (the room path, about ~y).
  const Eigen::Vector3d axis(1, 0, -2);
  auto stage = makeStage("estimate_extrinsic = rotation\n" + rotatedCamera(2.0, axis));
  const Eigen::Matrix3d believed = Eigen::AngleAxisd(2.0 * M_PI / 180, axis.normalized()).matrix();
  double left_deg = 0, worst_camera_deg = 0, sum_sq = 0;
  int frames = 0;
  Eigen::Matrix3d first = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; source.time(i) <= 10; ++i) {
    core::Frame f = source.frame(i);
    stage->process(f);
    ASSERT_TRUE(f.T_world_camera.has_value());
    // The camera's rotation since the first frame against the truth's (the world is the first
    // body frame, which the believed rotation puts 2 deg from the camera's).
    if (i == 0) first = f.T_world_camera->linear();
    const Eigen::Matrix3d turned = first.transpose() * f.T_world_camera->linear();
    const double camera_deg =
        Eigen::AngleAxisd(turned.transpose() * source.truth(i).linear()).angle() * 180 / M_PI;
    worst_camera_deg = std::max(worst_camera_deg, camera_deg);
    sum_sq += camera_deg * camera_deg;
    ++frames;
    if (!f.keyframe) continue;
    const Eigen::Matrix3d estimated =
        believed * quaternionExp(f.keyframe->extrinsic_rotation_change).toRotationMatrix();
    left_deg = Eigen::AngleAxisd(estimated).angle() * 180 / M_PI;  // the truth: identity
  }
  const double rms_camera_deg = std::sqrt(sum_sq / frames);
  std::printf(
      "2 deg extrinsic rotation error: %.3f deg left at 10 s; the camera's orientation "
      "%.3f deg off (RMS), at most %.3f deg\n",
      left_deg, rms_camera_deg, worst_camera_deg);
  EXPECT_LT(left_deg, 0.2);
  EXPECT_LT(rms_camera_deg, 0.2);
}
