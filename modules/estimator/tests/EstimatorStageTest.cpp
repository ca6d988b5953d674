// EstimatorStage on synthetic frames (SyntheticFrames.h: the room's corner seen as tracked
// features from a known path, with the path's IMU samples), run directly, frame by frame.
#include "SyntheticFrames.h"

#include <dynslam/estimator/EstimatorStage.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using namespace dynslam;
using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

std::unique_ptr<EstimatorStage> makeStage(const std::string& settings = "") {
  auto stage = std::make_unique<EstimatorStage>();
  stage->configure(core::IniConfig::fromText("[Estimator]\n" + settings), "Estimator");
  return stage;
}

/// The keyframes' records, in order.
std::vector<core::KeyframeRecord> keyframesOf(const std::vector<core::Frame>& frames) {
  std::vector<core::KeyframeRecord> out;
  for (const auto& f : frames)
    if (f.keyframe) out.push_back(*f.keyframe);
  return out;
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
    std::vector<core::Frame> frames;
    for (std::size_t i = 0; i < 45; ++i) {
      frames.push_back(source.frame(i));
      if (blackStart && i == 0) frames.back().features.clear();
      stage->process(frames.back());
    }
    const auto keyframes = keyframesOf(frames);
    ASSERT_GE(keyframes.size(), 14u);
    EXPECT_EQ(keyframes.front().static_features == 0, blackStart);
    // window_size = 10: the window is full at keyframe 9, and the featureless keyframe leaves
    // it when keyframe 10 comes.
    EXPECT_EQ(firstVisualInertial(keyframes), blackStart ? 10 : 9);
  }
}

// [Estimator] is read through EstimatorOptions::describe(): a value outside a key's range, or a
// setting that acts only through another one left off, is refused naming the keys.
TEST(EstimatorOptions, RefusesValuesOutOfRangeAndSettingsThatWouldDoNothing) {
  const auto refusal = [](const std::string& settings) -> std::string {
    try {
      makeStage(settings);
    } catch (const core::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal("window_size = 1\n").find("window_size"), std::string::npos);
  EXPECT_NE(refusal("pnp_max_imu_correction_m = -0.1\n").find("pnp_max_imu_correction_m"),
            std::string::npos);
  EXPECT_NE(refusal("gravity = 9.81 m/s^2\n").find("gravity"), std::string::npos);
  for (const std::string key : {"gnss_uere_horizontal = 0.025", "gnss_lever_arm_z = 0.5"}) {
    const std::string why = refusal(key + "\n");
    EXPECT_NE(why.find(key.substr(0, key.find(' '))), std::string::npos) << why;
    EXPECT_NE(why.find("use_gnss"), std::string::npos) << why;
    EXPECT_EQ(refusal(key + "\nuse_gnss = true\n"), "");
  }
  const std::string why = refusal("dynamic_handling = remove\nrigid_factors = false\n");
  EXPECT_NE(why.find("rigid_factors"), std::string::npos) << why;
  EXPECT_NE(why.find("dynamic_handling = full"), std::string::npos) << why;
  EXPECT_EQ(refusal("dynamic_handling = full\nrigid_factors = false\n"), "");
  EXPECT_EQ(refusal("dynamic_handling = remove\n"), "");
}
