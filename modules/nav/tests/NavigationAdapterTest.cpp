#include "FakeEstimateSource.h"

#include <dynslam/nav/NavigationAdapter.h>

#include <mrpt/maps/CSimplePointsMap.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace dynslam::nav {
namespace {

using testing::FakeEstimateSource;
using testing::planarPose;

/// Points of an obstacle map as (x, y, z).
std::vector<Eigen::Vector3d> pointsOf(const mrpt::maps::CSimplePointsMap& map) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < map.size(); ++i) {
    float x, y, z;
    map.getPoint(i, x, y, z);
    out.emplace_back(x, y, z);
  }
  return out;
}

class NavigationAdapterTest : public ::testing::Test {
 protected:
  NavigationAdapterTest() {
    options.camera_x = 0.1;
    options.camera_z = 0.6;
    options.camera_pitch_deg = 10;  // looking a little down
    // A map frame like a visual-inertial run's: neither the robot's start nor level with it.
    Eigen::Isometry3d T_nav_map = Eigen::Isometry3d::Identity();
    T_nav_map.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                          Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitX()))
                             .toRotationMatrix();
    T_nav_map.translation() = Eigen::Vector3d(0.4, -2.0, 0.6);
    const auto& o = options;
    source = std::make_unique<FakeEstimateSource>(
        T_nav_map, core::opticalFrameOnBody({o.camera_x, o.camera_y, o.camera_z}, o.camera_yaw_deg,
                                            o.camera_pitch_deg, o.camera_roll_deg));
  }

  NavigationOptions options;
  std::unique_ptr<FakeEstimateSource> source;
};

TEST_F(NavigationAdapterTest, ThePoseIsTheRobotsBaseInTheFrameOfItsStart) {
  NavigationAdapter adapter(*source, options);
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  source->robotAt(5.0, planarPose(1.0, 0.5, M_PI / 2));
  mrpt::math::TPose2D pose, odometry;
  mrpt::math::TTwist2D velocity;
  mrpt::system::TTimeStamp stamp;
  std::string frame;
  ASSERT_TRUE(adapter.getCurrentPoseAndSpeeds(pose, velocity, stamp, odometry, frame));
  EXPECT_NEAR(pose.x, 1.0, 1e-9);
  EXPECT_NEAR(pose.y, 0.5, 1e-9);
  EXPECT_NEAR(pose.phi, M_PI / 2, 1e-9);
  EXPECT_EQ(odometry, pose);
  EXPECT_EQ(frame, "map");
  EXPECT_NEAR(mrpt::Clock::toDouble(stamp), 5.0, 1e-6);
  // 5 s between the two poses: too far apart for a velocity.
  EXPECT_EQ(velocity.vx, 0.0);
  EXPECT_EQ(velocity.omega, 0.0);
}

TEST_F(NavigationAdapterTest, TheVelocityIsTheWorldVelocityOfTheLastTwoPoses) {
  NavigationAdapter adapter(*source, options);
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  source->robotAt(1.0, planarPose(0, 0, M_PI / 2));
  source->robotAt(1.1, planarPose(0, 0.1, M_PI / 2 + 0.05));
  mrpt::math::TPose2D pose, odometry;
  mrpt::math::TTwist2D v;
  mrpt::system::TTimeStamp stamp;
  std::string frame;
  ASSERT_TRUE(adapter.getCurrentPoseAndSpeeds(pose, v, stamp, odometry, frame));
  EXPECT_NEAR(v.vx, 0.0, 1e-6);  // world axes: driving along the start's y
  EXPECT_NEAR(v.vy, 1.0, 1e-6);
  EXPECT_NEAR(v.omega, 0.5, 1e-6);
}

TEST_F(NavigationAdapterTest, NothingWhileTheSystemInitializesOrIsLost) {
  NavigationAdapter adapter(*source, options);
  mrpt::math::TPose2D pose, odometry;
  mrpt::math::TTwist2D v;
  mrpt::system::TTimeStamp stamp;
  std::string frame;
  mrpt::maps::CSimplePointsMap obstacles;
  source->status_ = system::TrackingStatus::Initializing;
  EXPECT_FALSE(adapter.getCurrentPoseAndSpeeds(pose, v, stamp, odometry, frame));
  EXPECT_FALSE(adapter.senseObstacles(obstacles, stamp));
  source->status_ = system::TrackingStatus::Tracking;  // but no pose yet
  EXPECT_FALSE(adapter.getCurrentPoseAndSpeeds(pose, v, stamp, odometry, frame));
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(adapter.getCurrentPoseAndSpeeds(pose, v, stamp, odometry, frame));
  EXPECT_TRUE(adapter.senseObstacles(obstacles, stamp));
  source->status_ = system::TrackingStatus::LostRestarting;
  EXPECT_FALSE(adapter.getCurrentPoseAndSpeeds(pose, v, stamp, odometry, frame));
  EXPECT_FALSE(adapter.senseObstacles(obstacles, stamp));
}

TEST_F(NavigationAdapterTest, AWalkersObstaclesLieOnItsPredictedPathInTheRobotFrame) {
  options.obstacle_horizon_s = 1.5;
  NavigationAdapter adapter(*source, options);
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  source->robotAt(1.0, planarPose(1.0, 0, M_PI / 2));  // facing the start's y
  source->personAt({3.0, 0, 0.9}, {0, 1.0, 0});        // crossing in front, left to right
  mrpt::maps::CSimplePointsMap obstacles;
  mrpt::system::TTimeStamp stamp;
  ASSERT_TRUE(adapter.senseObstacles(obstacles, stamp));
  const auto points = pointsOf(obstacles);
  ASSERT_FALSE(points.empty());
  // In the robot's frame the person stands 2 m to its right and walks forward along x.
  const Eigen::Vector2d from(0, -2), to(1.5, -2);
  const double radius = 0.25;  // its width 0.5 m
  double farthest = -1e9;
  for (const auto& p : points) {
    const double t = std::clamp(p.x() - from.x(), 0.0, to.x() - from.x());
    EXPECT_LE((p.head<2>() - (from + Eigen::Vector2d(t, 0))).norm(), radius + 1e-4)
        << p.transpose();
    EXPECT_GT(p.z(), 0.01);
    EXPECT_LE(p.z(), 1.8 + 1e-4);
    farthest = std::max(farthest, p.x());
  }
  EXPECT_NEAR(farthest, to.x() + radius, 0.01);

  options.obstacle_horizon_s = 0;  // its current footprint only
  NavigationAdapter now(*source, options);
  ASSERT_TRUE(now.senseObstacles(obstacles, stamp));
  for (const auto& p : pointsOf(obstacles)) EXPECT_LE((p.head<2>() - from).norm(), radius + 1e-4);
}

TEST_F(NavigationAdapterTest, ASlowObjectKeepsItsCurrentFootprint) {
  NavigationAdapter adapter(*source, options);
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  source->personAt({2.0, 1.0, 0.9}, {0.1, 0, 0});  // below moving_speed_m_s
  mrpt::maps::CSimplePointsMap obstacles;
  mrpt::system::TTimeStamp stamp;
  ASSERT_TRUE(adapter.senseObstacles(obstacles, stamp));
  ASSERT_GT(obstacles.size(), 0u);
  for (const auto& p : pointsOf(obstacles))
    EXPECT_LE((p.head<2>() - Eigen::Vector2d(2.0, 1.0)).norm(), 0.25 + 1e-4);
}

TEST_F(NavigationAdapterTest, StaticMapPointsAboveTheFloorAndInRangeOnly) {
  NavigationAdapter adapter(*source, options);
  source->robotAt(0.0, Eigen::Isometry3d::Identity());
  std::vector<Eigen::Vector3d> map;
  for (double x = -1; x <= 3; x += 0.1) map.emplace_back(x, 0.5, 0.0);      // the floor
  map.emplace_back(1.0, 0.5, 0.03);                                         // floor noise
  for (double z = 0.1; z < 1.45; z += 0.02) map.emplace_back(2.0, 0.0, z);  // a post
  map.emplace_back(9.0, 0.0, 1.0);  // beyond obstacle_range_m
  map.emplace_back(1.0, 0.0, 2.5);  // above max_obstacle_height_m
  source->mapOf(map);
  mrpt::maps::CSimplePointsMap obstacles;
  mrpt::system::TTimeStamp stamp;
  ASSERT_TRUE(adapter.senseObstacles(obstacles, stamp));
  auto points = pointsOf(obstacles);
  // The post, one point per 0.3 m band (footprint_height_step_m): 0.1-1.44 m spans 5 bands.
  ASSERT_EQ(points.size(), 5u);
  for (const auto& p : points) {
    EXPECT_NEAR(p.x(), 2.0, 1e-4);
    EXPECT_NEAR(p.y(), 0.0, 1e-4);
    EXPECT_GE(p.z(), 0.05);
  }
  // The robot drove to (1, 1) and turned left: the post is 1 m behind it and 1 m to its right.
  source->robotAt(1.0, planarPose(1.0, 1.0, M_PI / 2));
  ASSERT_TRUE(adapter.senseObstacles(obstacles, stamp));
  points = pointsOf(obstacles);
  ASSERT_EQ(points.size(), 5u);
  for (const auto& p : points) {
    EXPECT_NEAR(p.x(), -1.0, 1e-4);
    EXPECT_NEAR(p.y(), -1.0, 1e-4);
  }
}

}  // namespace
}  // namespace dynslam::nav
