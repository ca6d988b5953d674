// MRPT's reactive navigator driven through SlamRobotInterface: it moves towards its target while
// the system tracks, and stops the robot when the pose becomes unavailable.
#include "FakeEstimateSource.h"

#include <dynslam/nav/SlamRobotInterface.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem3D.h>

#include <gtest/gtest.h>

namespace dynslam::nav {
namespace {

using testing::FakeEstimateSource;
using testing::planarPose;

/// A robot that records the navigator's commands; time is the test's.
class RecordingRobot : public SlamRobotInterface {
 public:
  using SlamRobotInterface::SlamRobotInterface;
  double now = 0;
  double last_v = 0;
  int commands = 0, stops = 0, emergency_stops = 0;

  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& cmd) override {
    ++commands;
    last_v = cmd.getVelCmdElement(0);
    return true;
  }
  bool stop(bool emergency) override {
    ++(emergency ? emergency_stops : stops);
    last_v = 0;
    return true;
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override {
    return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
  double getNavigationTime() override { return now; }
  void resetNavigationTimer() override { now = 0; }
};

class ReactiveNavigatorTest : public ::testing::Test {
 protected:
  ReactiveNavigatorTest()
      : source(Eigen::Isometry3d::Identity(),
               core::opticalFrameOnBody({0, 0, options.camera_z}, 0, 0, 0)),
        adapter(source, options),
        robot(adapter),
        navigator(robot, false, false) {
    // The robot of the navigation scenarios (a 0.5 m base, two PTGs).
    navigator.loadConfigFile(
        mrpt::config::CConfigFile(dynslam::testing::sourceDir() + "/params/nav/reactive3d.ini"));
    navigator.params_abstract_ptg_navigator.ptg_cache_files_directory =
        dynslam::testing::scratchDir("ptg");
    navigator.initialize();
  }

  void navigateTo(double x, double y) {
    mrpt::nav::CAbstractPTGBasedReactive::TNavigationParamsPTG params;
    params.target.target_coords = mrpt::math::TPose2D(x, y, 0);
    params.target.targetAllowedDistance = 0.3;
    navigator.navigate(&params);
  }
  void step() {
    robot.now += 0.1;
    navigator.navigationStep();
  }

  NavigationOptions options;
  FakeEstimateSource source;
  NavigationAdapter adapter;
  RecordingRobot robot;
  mrpt::nav::CReactiveNavigationSystem3D navigator;
};

TEST_F(ReactiveNavigatorTest, DrivesTowardsItsTargetWhileTheSystemTracks) {
  source.robotAt(0.0, Eigen::Isometry3d::Identity());
  navigateTo(3.0, 0.0);
  step();
  EXPECT_EQ(navigator.getCurrentState(), mrpt::nav::CAbstractNavigator::NAVIGATING);
  EXPECT_GE(robot.commands, 1);
  EXPECT_GT(robot.last_v, 0.1);
  EXPECT_EQ(robot.emergency_stops, 0);
}

// MRPT 2.5's navigator stops the robot (an emergency stop) at every step whose pose query fails
// and stays in NAVIGATING, so it drives on once the pose is back.
TEST_F(ReactiveNavigatorTest, StopsTheRobotWhileThePoseIsLostAndGoesOnAfter) {
  source.robotAt(0.0, Eigen::Isometry3d::Identity());
  navigateTo(3.0, 0.0);
  step();
  ASSERT_GT(robot.last_v, 0.1);
  source.robotAt(0.1, planarPose(0.1, 0, 0));
  source.status_ = system::TrackingStatus::LostRestarting;
  const int commands = robot.commands;
  for (int i = 0; i < 3; ++i) {
    step();
    EXPECT_EQ(robot.last_v, 0.0);
  }
  EXPECT_EQ(robot.emergency_stops, 3);
  EXPECT_EQ(robot.commands, commands);  // no motion command while lost
  source.status_ = system::TrackingStatus::Tracking;
  source.robotAt(0.5, planarPose(0.1, 0, 0));
  step();
  EXPECT_GT(robot.last_v, 0.1);
}

TEST_F(ReactiveNavigatorTest, NeverMovesWhileTheSystemInitializes) {
  source.status_ = system::TrackingStatus::Initializing;
  navigateTo(3.0, 0.0);
  for (int i = 0; i < 5; ++i) step();
  EXPECT_EQ(robot.emergency_stops, 5);
  EXPECT_EQ(robot.commands, 0);
  EXPECT_EQ(robot.last_v, 0.0);
}

}  // namespace
}  // namespace dynslam::nav
