// The feature tracker on real Kinect frames (../shared/data/7scenes, a static room): converted
// by sevenscenes2rawlog and read back through io as the pipeline does.
#include "MethodSettings.h"

#include <dynslam/frontend/FeatureTracker.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <map>

using namespace dynslam;
namespace dt = dynslam::testing;

TEST(FeatureTrackerSevenScenes, TracksAStaticRoomWithFewRejections) {
  DYNSLAM_REQUIRE_SHARED(scenes, "data/7scenes");
  const std::string out = dt::scratchDir();
  const auto conv = dt::runCommand(dt::binDir() + "/sevenscenes2rawlog --in '" + scenes +
                                   "' --out '" + out + "/7s.rawlog' --last 89");
  ASSERT_EQ(conv.exit_code, 0) << conv.output;

  io::RawlogSource source(out + "/7s.rawlog");
  io::SensorSync sync;
  std::vector<core::Frame> frames;
  while (auto obs = source.next()) sync.push(obs, frames);
  sync.flush(frames);
  ASSERT_EQ(frames.size(), 90u);

  frontend::FeatureTracker tracker(frontend::testing::methodTracking());
  size_t features = 0, withDepth = 0, lengthSum = 0, incoming = 0, lostRansac = 0, lost = 0;
  for (const auto& f : frames) {
    const auto out = tracker.track(f);
    const auto& s = tracker.lastStats();
    EXPECT_FALSE(s.gyro_used) << "7-Scenes has no IMU";
    EXPECT_GE(out.size(), 140u) << "frame " << f.index;
    features += out.size();
    for (const auto& feature : out) {
      withDepth += feature.depth > 0;
      lengthSum += size_t(feature.track_length);
    }
    incoming += size_t(s.incoming);
    lostRansac += size_t(s.lost_ransac);
    lost += size_t(s.lost_klt + s.lost_fb + s.lost_ransac);
  }
  const double meanAge = double(lengthSum) / double(features);
  std::cout << "90 frames: mean age of a frame's features " << meanAge << " frames, depth on "
            << 100.0 * withDepth / features << " %, lost " << 100.0 * lost / incoming
            << " % per frame (RANSAC " << 100.0 * lostRansac / incoming << " %)\n";
  EXPECT_GT(meanAge, 8.0) << "measured 21";
  // The depth camera (f 585 px) sees less than the colour camera (f 525 px): registered, its
  // depth covers 0.90 x 0.90 of the colour image, and corners crowd the borders (measured 72 %).
  EXPECT_GT(double(withDepth) / features, 0.65);
  EXPECT_LT(double(lostRansac) / incoming, 0.03) << "a static room: few epipolar outliers (1.2 %)";
  EXPECT_LT(double(lost) / incoming, 0.10) << "measured 4 %";
}
