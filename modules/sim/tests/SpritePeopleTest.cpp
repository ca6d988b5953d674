// Real-appearance people in the simulator ([People] appearance = video): a sprite bank cut from
// a synthetic walker video dresses the room's people, who are drawn, z-tested and scored as
// rendered people are.
#include "SmallScenario.h"

#include <dynslam/core/Config.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/sim/SpriteExtractor.h>
#include <dynslam/testing/SyntheticWalkers.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <algorithm>

namespace dynslam::sim {
namespace {

/// A bank of one walker crossing a synthetic video (the colours of its stripes: blue and red).
std::string walkerBank(const std::string& dir) {
  dynslam::testing::SyntheticWalkerScene scene;
  scene.walkers.push_back({{80, 320}, {560, 320}});
  std::vector<cv::Mat> samples;
  for (int i = 0; i < scene.frames; i += 3) samples.push_back(scene.frame(i));
  SpriteExtractor extractor(medianBackground(samples));
  for (int i = 0; i < scene.frames; ++i) extractor.add(scene.frame(i));
  writeSpriteBank(extractor.finish("walker.avi"), dir);
  return dir;
}

ScenarioOptions videoPeople(const std::string& bank) {
  ScenarioOptions o = sim::testing::smallScenario("room", 3.0, 10, 3);
  o.people.walkers = 3;
  o.people.standing = 1;
  o.people.appearance = "video";
  o.people.sprites = bank;
  return o;
}

TEST(SimSpritePeople, RealAppearancePeopleAreDrawnAndScoredAsRenderedOnesAre) {
  const Simulator sim(videoPeople(walkerBank(dynslam::testing::scratchDir() + "/bank")));
  SimFrame f;
  size_t seen = 0, spriteColoured = 0;
  for (size_t i = 0; i < sim.frameCount(); i += 3) {
    sim.renderFrame(i, f);
    for (const auto& o : f.objects) {
      const cv::Mat mask = f.image.label == o.id;
      EXPECT_EQ(cv::countNonZero(mask(o.box)), cv::countNonZero(mask)) << "frame " << i;
      EXPECT_EQ(cv::countNonZero(mask), o.visible_pixels);
      EXPECT_GT(o.visible_fraction, 0.0);
      EXPECT_LE(o.visible_fraction, 1.0);
      EXPECT_EQ(o.category, "person");
      if (o.visible_pixels < 200) continue;
      ++seen;
      // The person's pixels hold the walker's clothes (saturated blue or red stripes), and its
      // depth is a body's: within 0.3 m of its median over the mask.
      cv::Scalar meanColour = cv::mean(f.image.rgb, mask);
      spriteColoured += std::abs(meanColour[0] - meanColour[2]) > 20 || meanColour[1] < 80;
      std::vector<float> depths;
      for (int y = 0; y < mask.rows; ++y)
        for (int x = 0; x < mask.cols; ++x)
          if (mask.at<uchar>(y, x) && f.image.depth.at<float>(y, x) > 0)
            depths.push_back(f.image.depth.at<float>(y, x));
      std::sort(depths.begin(), depths.end());
      const double lo = depths[depths.size() / 20], hi = depths[depths.size() * 19 / 20];
      EXPECT_LT(hi - lo, 0.4 + 0.05 * hi)
          << "one body's depth, frame " << i << " id " << o.id << ": " << lo << " - " << hi;
    }
  }
  EXPECT_GT(seen, 5u) << "people in view";
  EXPECT_GT(spriteColoured, seen / 2) << "wearing the sprite's clothes";
}

TEST(SimSpritePeople, VideoAppearanceWithoutABankIsAnErrorNamingTheKeyOrFolder) {
  const auto load = [](const std::string& text) {
    ScenarioOptions o;
    o.load(core::IniConfig::fromText(text, "test.ini"));
    return o;
  };
  try {
    load("[People]\nappearance = video\n");
    FAIL() << "appearance = video without sprites";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sprites"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load("[People]\nsprites = /tmp/bank\n"), core::ConfigError)
      << "sprites without appearance = video";
  try {
    Simulator sim(videoPeople("/nonexistent/bank"));
    FAIL() << "a missing bank";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/bank"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynslam::sim
