// The adapter served by a running System (SystemEstimateSource): two simulated seconds of
// indoor_people_high (three people walking, one standing) fed observation by observation, the
// navigator's two calls made between them as a navigation thread would.
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/nav/NavigationAdapter.h>
#include <dynslam/nav/SystemEstimateSource.h>
#include <dynslam/system/System.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/maps/CSimplePointsMap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dynslam::nav {
namespace {

using dynslam::testing::binDir;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

TEST(NavigationSystem, PoseAndObstaclesComeFromTheRunningSystem) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_high.ini --out " + dir +
                                 " --set Scenario.duration=2 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;

  system::SystemSettings settings;
  settings.synchronous = true;
  system::System slam(sourceDir() + "/params/sim_vio.ini",
                      {"Detection.objects=" + dir + "/objects.txt",
                       "Estimator.dynamic_handling=full", "Estimator.max_solver_time=100"},
                      settings);
  SystemEstimateSource source(slam);
  // The scenario's camera circles the room at 1.4 m looking at 1.2 m across a 1.8 m radius: a
  // robot carrying it that high, pitched that much down.
  NavigationOptions options;
  options.camera_z = 1.4;
  options.camera_pitch_deg = std::atan2(0.2, 1.8) * 180 / M_PI;
  NavigationAdapter adapter(source, options);

  io::RawlogSource rawlog(dir + "/sim.rawlog");
  int answered = 0, withPeople = 0;
  std::size_t mostObstacles = 0;
  mrpt::math::TPose2D pose, odometry;
  mrpt::math::TTwist2D velocity;
  mrpt::system::TTimeStamp stamp;
  std::string frame;
  mrpt::maps::CSimplePointsMap obstacles;
  while (auto observation = rawlog.next()) {
    slam.onNewObservation(observation);
    if (!adapter.getCurrentPoseAndSpeeds(pose, velocity, stamp, odometry, frame)) continue;
    ++answered;
    ASSERT_TRUE(adapter.senseObstacles(obstacles, stamp));
    mostObstacles = std::max(mostObstacles, obstacles.size());
    if (!source.movingObjects().empty()) ++withPeople;
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      float x, y, z;
      obstacles.getPoint(i, x, y, z);
      ASSERT_GE(z, options.floor_clearance_m - 1e-4);
      ASSERT_LE(std::hypot(x, y), options.obstacle_range_m + 1e-3);
    }
  }
  slam.flush();
  EXPECT_GT(answered, 100);  // of ~470 observations (60 frames, 400 IMU samples)
  EXPECT_GT(withPeople, 50);
  EXPECT_GT(mostObstacles, 100u);

  // The robot's way from its start: the camera's horizontal way in the ground truth (the camera
  // sits above the base's origin here).
  ASSERT_TRUE(adapter.getCurrentPoseAndSpeeds(pose, velocity, stamp, odometry, frame));
  const auto truth = core::readTum(dir + "/groundtruth.tum");
  ASSERT_GE(truth.size(), 2u);
  const Eigen::Vector3d first = truth.front().T_world_body.translation();
  const auto* last = core::poseNear(truth, mrpt::Clock::toDouble(stamp), 0.02);
  ASSERT_NE(last, nullptr);
  const double travelled = (last->T_world_body.translation() - first).head<2>().norm();
  std::printf("answered %d, with people %d, most obstacles %zu; way %.3f m, true %.3f m\n",
              answered, withPeople, mostObstacles, std::hypot(pose.x, pose.y), travelled);
  EXPECT_GT(travelled, 0.5);
  EXPECT_NEAR(std::hypot(pose.x, pose.y), travelled, 0.03);
}

}  // namespace
}  // namespace dynslam::nav
