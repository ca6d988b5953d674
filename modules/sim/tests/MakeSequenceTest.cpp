// makeSequence: the one choice between the Simulator and the Augmenter that dynslam-sim and
// bench-segmentation share. The augment case needs ../shared/data/7scenes (skipped without).
#include "SmallScenario.h"

#include <dynslam/core/Config.h>
#include <dynslam/sim/Augmenter.h>
#include <dynslam/sim/MakeSequence.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <set>

namespace dynslam::sim {
namespace {

TEST(MakeSequence, SyntheticScenesGetTheSimulator) {
  const ScenarioOptions o = testing::smallScenario("room", 1.0, 10, 3);
  const auto sequence = makeSequence(o);
  ASSERT_NE(dynamic_cast<const Simulator*>(sequence.get()), nullptr);
  const Simulator direct(o);
  ASSERT_EQ(sequence->frameCount(), direct.frameCount());
  SimFrame a, b;
  sequence->renderFrame(5, a);
  direct.renderFrame(5, b);
  EXPECT_EQ(cv::countNonZero(a.image.label != b.image.label), 0) << "the same scene";
}

// What bench-segmentation scores on an augment scene: the inserted people's boxes and instance
// labels in the real frames, and nothing labelled that is not listed.
TEST(MakeSequence, AugmentSceneGetsTheAugmenterWithLabelsInsideTheBoxes) {
  DYNSLAM_REQUIRE_SHARED(scenes, "data/7scenes");
  const std::string rawlog = dynslam::testing::scratchDir() + "/7scenes.rawlog";
  const auto conversion =
      dynslam::testing::runCommand(dynslam::testing::binDir() + "/sevenscenes2rawlog --in '" +
                                   scenes + "' --out '" + rawlog + "' --first 90 --last 150");
  ASSERT_EQ(conversion.exit_code, 0) << conversion.output;
  ScenarioOptions o;
  o.load(core::IniConfig::fromText(
      "[Scenario]\nscene = augment\nseed = 3\n[People]\nwalkers = 2\nstanding = 1\n"
      "[Augment]\nrawlog = " +
          rawlog + "\nfloor_frames = 12\nclearance = 0.1\n",
      "make-sequence test ini"));
  const auto sequence = makeSequence(o);
  ASSERT_NE(dynamic_cast<const Augmenter*>(sequence.get()), nullptr);
  ASSERT_EQ(sequence->frameCount(), 61u);  // the real frames, not [Scenario] duration
  EXPECT_EQ(sequence->camera().width, 640);
  size_t people = 0;
  for (size_t i = 0; i < sequence->frameCount(); i += 10) {
    SimFrame f;
    sequence->renderFrame(i, f);
    ASSERT_EQ(f.image.label.size(), cv::Size(640, 480));
    std::set<uint16_t> listed;
    for (const ObjectTruth& obj : f.objects) {
      listed.insert(obj.id);
      if (obj.visible_pixels == 0) continue;
      ++people;
      const cv::Mat mine = f.image.label == obj.id;
      EXPECT_EQ(cv::countNonZero(mine(obj.box)), obj.visible_pixels) << "frame " << i;
    }
    for (int y = 0; y < f.image.label.rows; ++y)
      for (int x = 0; x < f.image.label.cols; ++x) {
        const uint16_t l = f.image.label.at<uint16_t>(y, x);
        if (l != 0 && !listed.count(l)) FAIL() << "frame " << i << ": unlisted label " << l;
      }
  }
  EXPECT_GT(people, 5u);
}

}  // namespace
}  // namespace dynslam::sim
