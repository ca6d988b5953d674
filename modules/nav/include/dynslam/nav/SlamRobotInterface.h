#pragma once
// A CRobot2NavInterface whose sensing side is the SLAM estimate (NavigationAdapter); a robot
// derives from it and implements the motion side (changeSpeeds, stop, getStopCmd,
// getEmergencyStopCmd) for its own base:
//
//   class MyRobot : public dynslam::nav::SlamRobotInterface {
//     using SlamRobotInterface::SlamRobotInterface;
//     bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& cmd) override { ... }
//     ...
//   };
//   MyRobot robot(adapter);
//   mrpt::nav::CReactiveNavigationSystem3D navigator(robot);
#include <dynslam/nav/NavigationAdapter.h>

#include <mrpt/nav/reactive/CRobot2NavInterface.h>

namespace dynslam::nav {

class SlamRobotInterface : public mrpt::nav::CRobot2NavInterface {
 public:
  /// `adapter` must outlive this interface.
  explicit SlamRobotInterface(const NavigationAdapter& adapter) : adapter_(adapter) {}

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) override {
    return adapter_.getCurrentPoseAndSpeeds(pose, velocity, timestamp, odometry, frame_id);
  }
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                      mrpt::system::TTimeStamp& timestamp) override {
    return adapter_.senseObstacles(obstacles, timestamp);
  }

 protected:
  const NavigationAdapter& adapter_;
};

}  // namespace dynslam::nav
