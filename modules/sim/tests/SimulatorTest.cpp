#include "SmallScenario.h"

#include <dynslam/sim/Simulator.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam::sim;

namespace {

/// indoor_people-like, but short and at a quarter of the resolution so the test stays fast.
ScenarioOptions smallScenario(uint64_t seed = 3) {
  ScenarioOptions o = dynslam::sim::testing::smallScenario("room", 3.0, 10, seed);
  o.people.walkers = 3;
  o.people.standing = 1;
  return o;
}

bool identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() &&
         std::equal(a.datastart, a.dataend, b.datastart);
}

}  // namespace

TEST(SimSimulator, FramesCameraAndImuLineUp) {
  const Simulator sim(smallScenario());
  EXPECT_EQ(sim.frameCount(), 31u);
  EXPECT_NEAR(sim.frameTime(30), 3.0, 1e-12);
  EXPECT_EQ(sim.imu().size(), 601u) << "200 Hz over [0, 3] s";
  SimFrame f;
  sim.renderFrame(12, f);
  const Eigen::Isometry3d expected = sim.trajectory().sample(1.2).T_world_body * sim.T_body_camera();
  EXPECT_TRUE(f.T_world_camera.isApprox(expected, 1e-12));
  // The camera looks horizontally-ish across the room: its optical axis is nearly level.
  EXPECT_LT(std::abs(f.T_world_camera.linear().col(2).z()), 0.3);
  EXPECT_EQ(f.image.rgb.size(), cv::Size(320, 240));
  EXPECT_GT(cv::countNonZero(f.image.depth > 0), 0.9 * 320 * 240) << "a closed room";
}

TEST(SimSimulator, GroundTruthBoxesEncloseTheInstanceLabels) {
  const Simulator sim(smallScenario());
  SimFrame f;
  size_t seen = 0, standingSeen = 0;
  for (size_t i = 0; i < sim.frameCount(); ++i) {
    sim.renderFrame(i, f);
    for (const auto& o : f.objects) {
      const cv::Mat mask = f.image.label == o.id;
      const int inside = cv::countNonZero(mask(o.box));
      EXPECT_EQ(inside, cv::countNonZero(mask)) << "frame " << i << " id " << o.id;
      EXPECT_EQ(inside, o.visible_pixels);
      EXPECT_GE(o.visible_fraction, 0.0);
      EXPECT_LE(o.visible_fraction, 1.0);
      EXPECT_EQ(o.category, "person");
      seen += o.visible_pixels > 0;
      standingSeen += !o.moving;
    }
  }
  EXPECT_GT(seen, 10u) << "people are in view";
  EXPECT_GT(standingSeen, 0u) << "the standing person is in view at some point";
}

TEST(SimSimulator, NobodyWalksThroughTheCamera) {
  const Simulator sim(smallScenario());
  SimFrame f;
  double nearest = 1e9;
  for (size_t i = 0; i < sim.frameCount(); ++i) {
    sim.renderFrame(i, f);
    for (int v = 0; v < f.image.label.rows; ++v)
      for (int u = 0; u < f.image.label.cols; ++u)
        if (f.image.label.at<uint16_t>(v, u) && f.image.depth.at<float>(v, u) > 0)
          nearest = std::min<double>(nearest, f.image.depth.at<float>(v, u));
  }
  EXPECT_GT(nearest, 0.3);
  EXPECT_LT(nearest, 2.5) << "but people do come close";
}

TEST(SimSimulator, SameSeedSameBytesOtherSeedOtherScene) {
  const Simulator a(smallScenario(5)), b(smallScenario(5)), c(smallScenario(6));
  SimFrame fa, fb, fc;
  a.renderFrame(17, fa);
  b.renderFrame(17, fb);
  c.renderFrame(17, fc);
  EXPECT_TRUE(identical(fa.image.rgb, fb.image.rgb));
  EXPECT_TRUE(identical(fa.image.depth, fb.image.depth));
  EXPECT_TRUE(identical(fa.image.label, fb.image.label));
  EXPECT_FALSE(identical(fa.image.rgb, fc.image.rgb));
  ASSERT_EQ(a.imu().size(), b.imu().size());
  for (size_t i = 0; i < a.imu().size(); i += 50) EXPECT_EQ(a.imu()[i].acc, b.imu()[i].acc);
  // Frames do not depend on the order they are rendered in.
  SimFrame again;
  a.renderFrame(3, again);
  a.renderFrame(17, again);
  EXPECT_TRUE(identical(fa.image.rgb, again.image.rgb));
}
