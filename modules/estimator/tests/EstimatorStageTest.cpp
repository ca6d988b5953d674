// EstimatorStage on synthetic frames (SyntheticFrames.h: the room's corner seen as tracked
// features from a known path, with the path's IMU samples), run directly, frame by frame.
#include "StageTestSupport.h"
#include "SyntheticFrames.h"

#include <dynslam/estimator/EstimatorStage.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace dynslam;
using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

/// The keyframes' records, in order.
std::vector<core::KeyframeRecord> keyframesOf(const std::vector<core::Frame>& frames) {
  std::vector<core::KeyframeRecord> out;
  for (const auto& f : frames)
    if (f.keyframe) out.push_back(*f.keyframe);
  return out;
}

/// Runs `frames` frames of `source` through `stage`; `alter` (optional) edits each before.
std::vector<core::Frame> run(EstimatorStage& stage, SyntheticFrames& source, std::size_t frames,
                             const std::function<void(core::Frame&)>& alter = {}) {
  std::vector<core::Frame> out;
  for (std::size_t i = 0; i < frames; ++i) {
    out.push_back(source.frame(i));
    if (alter) alter(out.back());
    stage.process(out.back());
  }
  stage.finish();
  return out;
}

/// RMS and largest distance of the camera positions written from the truth's; +inf when a frame
/// has no pose or a non-finite one.
std::pair<double, double> positionError(const std::vector<core::Frame>& frames,
                                        const SyntheticFrames& source) {
  double sum = 0, worst = 0;
  for (const auto& f : frames) {
    if (!f.T_world_camera || !f.T_world_camera->matrix().allFinite()) return {INFINITY, INFINITY};
    const double e = (f.T_world_camera->translation() - source.truth(f.index).translation()).norm();
    sum += e * e;
    worst = std::max(worst, e);
  }
  return {std::sqrt(sum / double(frames.size())), worst};
}

double statistic(const EstimatorStage& stage, const std::string& name) {
  for (const auto& [key, value] : stage.statistics())
    if (key == name) return value;
  ADD_FAILURE() << "no statistic " << name;
  return NAN;
}

/// Index among the keyframes of the first visual-inertial one, -1 when none.
int firstVisualInertial(const std::vector<core::KeyframeRecord>& keyframes) {
  for (std::size_t k = 0; k < keyframes.size(); ++k)
    if (keyframes[k].visual_inertial) return int(k);
  return -1;
}

}  // namespace

// The IMU alignment trusts the window's visual poses, so it is not tried while the window holds
// a keyframe that saw too little (fewer static features than keyframe_min_shared): here a black
// first frame, which becomes the window's first keyframe all the same. The window counts each
// keyframe's features itself, and they leave with the keyframe.
TEST(EstimatorStage, ImuInitializationWaitsUntilAFeaturelessKeyframeHasLeftTheWindow) {
  for (const bool blackStart : {false, true}) {
    SCOPED_TRACE(blackStart ? "black first frame" : "every frame sees the room");
    auto stage = makeStage();
    SyntheticFrames source;
    const auto frames = run(*stage, source, 45, [&](core::Frame& f) {
      if (blackStart && f.index == 0) f.features.clear();
    });
    const auto keyframes = keyframesOf(frames);
    ASSERT_GE(keyframes.size(), 14u);
    EXPECT_EQ(keyframes.front().static_features == 0, blackStart);
    // window_size = 10: the window is full at keyframe 9, and the featureless keyframe leaves
    // it when keyframe 10 comes.
    EXPECT_EQ(firstVisualInertial(keyframes), blackStart ? 10 : 9);
  }
}

// Without IMU samples the window stays RGB-D only (the constant-motion prior between
// keyframes), and every frame's pose follows the truth.
TEST(EstimatorStage, RgbdOnlyFollowsThePath) {
  auto stage = makeStage();
  SyntheticFramesOptions options;
  options.imu = false;
  SyntheticFrames source(options);
  const auto frames = run(*stage, source, 90);
  const auto [rms, worst] = positionError(frames, source);
  std::printf("RGB-D only, 3 s: position error RMS %.4f m, largest %.4f m\n", rms, worst);
  EXPECT_LT(rms, 0.01);
  EXPECT_LT(worst, 0.03);
  EXPECT_EQ(firstVisualInertial(keyframesOf(frames)), -1);
  EXPECT_EQ(statistic(*stage, "imu_initialized_at"), -1);
  EXPECT_EQ(statistic(*stage, "resets"), 0);
}

// On a path that accelerates enough the IMU initializes once the window is full; the window
// then estimates the body's velocity, and the poses follow the truth.
TEST(EstimatorStage, TheImuInitializesOnAnExcitingPathAndGivesTheVelocity) {
  auto stage = makeStage();
  SyntheticFrames source;
  const auto frames = run(*stage, source, 150);
  EXPECT_GE(statistic(*stage, "imu_initialized_at"), 0);
  EXPECT_LT(statistic(*stage, "imu_initialized_at"), 1.5) << "s";
  double worstVelocity = 0;
  int visualInertial = 0;
  for (const auto& f : frames)
    if (f.keyframe && f.keyframe->visual_inertial) {
      ++visualInertial;
      worstVelocity = std::max(
          worstVelocity, (f.keyframe->velocity - RoomPath::velocity(source.time(f.index))).norm());
    }
  EXPECT_GT(visualInertial, 30);
  EXPECT_LT(worstVelocity, 0.05) << "m/s";
  const auto [rms, worst] = positionError(frames, source);
  std::printf(
      "RGB-D + IMU, 5 s: position error RMS %.4f m, largest %.4f m; velocity error up "
      "to %.4f m/s\n",
      rms, worst, worstVelocity);
  EXPECT_LT(rms, 0.01);
  EXPECT_LT(worst, 0.03);
}

// A walker's features (NonRigid, on object 1) constrain the camera only with none; remove drops
// them, full gives them to r_D once the IMU is initialized (object_factors_wait_for_imu).
TEST(EstimatorStage, DynamicHandlingDecidesWhereAWalkersFeaturesGo) {
  SyntheticFramesOptions options;
  options.walker = true;
  for (const std::string handling : {"none", "remove", "full"}) {
    SCOPED_TRACE(handling);
    auto stage = makeStage("dynamic_handling = " + handling + "\n");
    SyntheticFrames source(options);
    int seenStatic = 0, seenWalker = 0, landmarks = 0, nonrigid = 0;
    const auto frames = run(*stage, source, 75);
    for (const auto& f : frames) {
      if (!f.keyframe) continue;
      for (const auto& feature : f.features) ++(feature.object_id < 0 ? seenStatic : seenWalker);
      landmarks += f.keyframe->static_features;
      nonrigid += f.keyframe->nonrigid_features;
    }
    ASSERT_GT(seenWalker, 0) << "the walker crosses the view";
    EXPECT_EQ(landmarks, handling == "none" ? seenStatic + seenWalker : seenStatic);
    if (handling == "remove") {
      EXPECT_EQ(nonrigid, 0);
    }
    if (handling == "full") {
      EXPECT_GT(nonrigid, 0);
    }
    if (handling != "none") {
      const auto [rms, worst] = positionError(frames, source);
      EXPECT_LT(rms, 0.01);
      EXPECT_LT(worst, 0.03);
    }
  }
}

// Failure detection: an estimate beyond a bound (here a max_speed below the path's) restarts the
// window from the last good pose; every frame still gets a pose near the truth, and the new
// window initializes the IMU again.
TEST(EstimatorStage, AFailureRestartsTheWindowAndPosesKeepComing) {
  auto stage = makeStage("max_speed = 0.1\n");
  SyntheticFrames source;
  const auto frames = run(*stage, source, 150);
  int restarts = 0;
  for (const auto& f : frames) restarts += f.keyframe && f.keyframe->restarted;
  EXPECT_GT(restarts, 0);
  EXPECT_EQ(statistic(*stage, "resets"), restarts);
  EXPECT_GE(statistic(*stage, "imu_init_attempts"), restarts) << "initialized again each time";
  const auto [rms, worst] = positionError(frames, source);
  std::printf("%d restarts: position error RMS %.4f m, largest %.4f m\n", restarts, rms, worst);
  EXPECT_LT(rms, 0.02);
  EXPECT_LT(worst, 0.05);
}

// [Estimator] is read through EstimatorOptions::describe(): a value outside a key's range, or a
// setting that acts only through another one left off, is refused naming the keys.
TEST(EstimatorOptions, RefusesValuesOutOfRangeAndSettingsThatWouldDoNothing) {
  EXPECT_NE(configRefusal("window_size = 1\n").find("window_size"), std::string::npos);
  EXPECT_NE(configRefusal("pnp_max_imu_correction_m = -0.1\n").find("pnp_max_imu_correction_m"),
            std::string::npos);
  EXPECT_NE(configRefusal("gravity = 9.81 m/s^2\n").find("gravity"), std::string::npos);
  for (const std::string key : {"gnss_uere_horizontal = 0.025", "gnss_lever_arm_z = 0.5"}) {
    const std::string why = configRefusal(key + "\n");
    EXPECT_NE(why.find(key.substr(0, key.find(' '))), std::string::npos) << why;
    EXPECT_NE(why.find("use_gnss"), std::string::npos) << why;
    EXPECT_EQ(configRefusal(key + "\nuse_gnss = true\n"), "");
  }
  const std::string why = configRefusal("dynamic_handling = remove\nrigid_factors = false\n");
  EXPECT_NE(why.find("rigid_factors"), std::string::npos) << why;
  EXPECT_NE(why.find("dynamic_handling = full"), std::string::npos) << why;
  EXPECT_EQ(configRefusal("dynamic_handling = full\nrigid_factors = false\n"), "");
  EXPECT_EQ(configRefusal("dynamic_handling = remove\n"), "");
}
