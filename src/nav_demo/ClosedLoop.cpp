#include "nav_demo/ClosedLoop.h"

#include "nav_demo/GroundTruthSource.h"
#include "nav_demo/StaticFootprint.h"
#include "nav_demo/TopView.h"

#include <dynslam/core/CameraMount.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/nav/NavigationAdapter.h>
#include <dynslam/nav/PlanarPose.h>
#include <dynslam/nav/SlamRobotInterface.h>
#include <dynslam/nav/SystemEstimateSource.h>
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/SensorLabels.h>
#include <dynslam/sim/DiffDriveMotion.h>
#include <dynslam/sim/ImuSynthesizer.h>
#include <dynslam/sim/Random.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/system/System.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem3D.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationIMU.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

namespace dynslam::navdemo {
namespace {

namespace fs = std::filesystem;
using WallClock = std::chrono::steady_clock;

using nav::planarOf;
using nav::planarPose;

double microseconds(WallClock::duration d) {
  return std::chrono::duration<double, std::micro>(d).count();
}

/// The simulated robot as the navigator sees it: the sensing side is the adapter (timed), the
/// motion commands go to the differential drive; the navigator's clock is the simulator's.
class SimulatedRobot : public nav::SlamRobotInterface {
 public:
  SimulatedRobot(const nav::NavigationAdapter& adapter, sim::DiffDriveMotion& motion,
                 ClosedLoopResult& result)
      : SlamRobotInterface(adapter), motion_(motion), result_(result) {
    logging_enable_console_output = false;  // "event not implemented" notes
  }

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame_id) override {
    const auto t0 = WallClock::now();
    has_pose_ = adapter_.getCurrentPoseAndSpeeds(pose, velocity, timestamp, odometry, frame_id);
    result_.pose_calls_us.push_back(microseconds(WallClock::now() - t0));
    return has_pose_;
  }
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                      mrpt::system::TTimeStamp& timestamp) override {
    const auto t0 = WallClock::now();
    const bool ok = adapter_.senseObstacles(obstacles, timestamp);
    result_.obstacle_calls_us.push_back(microseconds(WallClock::now() - t0));
    sensed_.clear();
    if (ok)
      for (std::size_t i = 0; i < obstacles.size(); ++i) {
        float x, y, z;
        obstacles.getPoint(i, x, y, z);
        sensed_.emplace_back(x, y);
      }
    return ok;
  }
  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& cmd) override {
    motion_.command(cmd.getVelCmdElement(0), cmd.getVelCmdElement(1));
    return true;
  }
  bool stop(bool emergency) override {
    motion_.command(0, 0);
    if (emergency) ++(has_pose_ ? result_.emergency_stops : result_.stops_without_pose);
    return true;
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override {
    return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
  double getNavigationTime() override { return motion_.t(); }
  void resetNavigationTimer() override {}

  /// The last obstacle set, robot frame x, y.
  const std::vector<Eigen::Vector2d>& sensed() const { return sensed_; }

 private:
  sim::DiffDriveMotion& motion_;
  ClosedLoopResult& result_;
  bool has_pose_ = false;
  std::vector<Eigen::Vector2d> sensed_;
};

/// MRPT's navigator without its table of call delays printed at exit (nav.json has the calls).
class Navigator : public mrpt::nav::CReactiveNavigationSystem3D {
 public:
  explicit Navigator(mrpt::nav::CRobot2NavInterface& robot)
      : CReactiveNavigationSystem3D(robot, false, false) {
    m_timlog_delays.enable(false);
    logging_enable_console_output = false;  // its messages are counted in nav.json
    enableTimeLog(false);
  }
};

/// Counts contacts: a body entering contact is one event (moving or not), staying in contact is
/// none; the minimum distance is kept.
class ContactCounter {
 public:
  /// `contact` holds the instant's t, id, robot speed and position.
  void observe(Contact contact, double limit, bool robotMoving, int& moving, int& still,
               double& minimum, std::vector<Contact>& log) {
    minimum = std::min(minimum, contact.distance_m);
    if (contact.distance_m >= limit) {
      in_contact_.erase(contact.id);
      return;
    }
    if (!in_contact_.insert(contact.id).second) return;
    ++(robotMoving ? moving : still);
    log.push_back(contact);
  }

 private:
  std::set<int> in_contact_;
};

std::string uniqueFeedName() {
  static std::atomic<int> counter{0};
  return "nav-demo-" + std::to_string(++counter);
}

}  // namespace

ClosedLoopResult runClosedLoop(const NavScenario& s, const sim::ScenarioOptions& worldOptions,
                               const ClosedLoopSettings& settings) {
  fs::create_directories(settings.out_dir);
  ClosedLoopResult result;
  const sim::Simulator world(worldOptions);
  const auto& w = world.options();
  const StaticFootprint statics(world.staticMesh(), s.navigation.floor_clearance_m,
                                s.navigation.max_obstacle_height_m);

  // The robot and its sensors: body = the base on the floor.
  sim::DiffDriveMotion motion(s.start.x(), s.start.y(), s.start.z(), 0.0, s.robot.limits);
  Eigen::Isometry3d T_body_imu = Eigen::Isometry3d::Identity();
  T_body_imu.translation() << s.robot.imu_x, s.robot.imu_y, s.robot.imu_z;
  const auto& n = s.navigation;
  const Eigen::Isometry3d T_body_camera =
      core::opticalFrameOnBody({n.camera_x, n.camera_y, n.camera_z}, n.camera_yaw_deg,
                               n.camera_pitch_deg, n.camera_roll_deg);
  std::mt19937_64 imuRng(sim::subSeed(w.world.seed, sim::kImuStream));
  sim::ImuNoiseProcess imu(w.imu.imu, imuRng);

  // What the navigator senses through: the SLAM system, or the truth.
  const bool estimated = s.demo.obstacles == "estimated";
  std::unique_ptr<system::System> slam;
  std::unique_ptr<nav::SystemEstimateSource> slamSource;
  std::unique_ptr<GroundTruthSource> truthSource;
  std::shared_ptr<core::ObjectGroundTruthFeed> feed;
  if (estimated) {
    std::vector<std::string> overrides = settings.slam_overrides;
    const auto slamIni = core::IniConfig::fromFile(s.demo.slam_config, overrides);
    if (slamIni.ini().read_string("Detection", "detector", "", false) == "ground_truth") {
      const std::string name = uniqueFeedName();
      feed = core::ObjectGroundTruthFeed::named(name);
      overrides.push_back("Detection.objects=" + std::string(core::ObjectGroundTruthFeed::kPrefix) +
                          name);
    }
    system::SystemSettings systemSettings;
    systemSettings.synchronous = true;
    systemSettings.map_update_min_frames = s.demo.map_min_frames;
    slam = std::make_unique<system::System>(s.demo.slam_config, overrides, systemSettings);
    slamSource = std::make_unique<nav::SystemEstimateSource>(*slam);
  } else {
    truthSource = std::make_unique<GroundTruthSource>(world.agents(), statics);
  }
  const nav::EstimateSource& source =
      estimated ? static_cast<const nav::EstimateSource&>(*slamSource) : *truthSource;
  const nav::NavigationAdapter adapter(source, n);
  SimulatedRobot robot(adapter, motion, result);
  Navigator navigator(robot);
  navigator.loadConfigFile(mrpt::config::CConfigFile(s.demo.navigator_config));
  navigator.params_abstract_ptg_navigator.ptg_cache_files_directory =
      (fs::path(settings.out_dir) / "ptg_cache").string();
  fs::create_directories(navigator.params_abstract_ptg_navigator.ptg_cache_files_directory);
  navigator.initialize();

  // Goals in the navigation frame: the robot's base at its start.
  const Eigen::Isometry3d T_world_start = planarPose(s.start);
  for (const auto& g : s.goals) result.goals.push_back({g});
  const auto navigateTo = [&](std::size_t i) {
    const Eigen::Vector3d g =
        T_world_start.inverse() * Eigen::Vector3d(s.goals[i].x(), s.goals[i].y(), 0);
    mrpt::nav::CAbstractPTGBasedReactive::TNavigationParamsPTG params;
    params.target.target_coords = mrpt::math::TPose2D(g.x(), g.y(), 0);
    params.target.targetAllowedDistance = s.demo.goal_tolerance_m;
    params.target.target_frame_id = n.frame_id;
    navigator.navigate(&params);
  };

  std::ofstream people((fs::path(settings.out_dir) / "people.csv").string());
  people << "t,id,category,x,y,vx,vy,moving\n";
  TopView view(statics, s.goals,
               settings.video ? (fs::path(settings.out_dir) / "top.avi").string() : "",
               s.demo.control_rate_hz);
  rawlog_tools::ColourImageStore images(rawlog_tools::ImageStorage::Embedded, "");
  ContactCounter peopleContacts, staticContacts;

  const double imuDt = 1.0 / w.imu.imu.rate_hz, frameDt = 1.0 / w.world.fps,
               controlDt = 1.0 / s.demo.control_rate_hz;
  const double endT = s.demo.wait_s + s.goals.size() * s.demo.goal_time_limit_s + 1.0;
  const auto stamp = [&](double t) { return w.world.start_time + t; };
  std::size_t goal = 0, frameIndex = 0;
  bool navigating = false;
  double goalStart = 0, nextFrame = 0, nextControl = 0;
  double reachedAt = -1;  // when the true position first came within the tolerance (< 0: not yet)
  const auto cameraPose = [&] { return motion.sample().T_world_body * T_body_camera; };
  const auto distanceToGoal = [&] {
    return (motion.sample().T_world_body.translation().head<2>() - s.goals[goal]).norm();
  };
  // Records the goal in hand as ended at t.
  const auto endGoal = [&](double t) {
    auto& r = result.goals[goal];
    r.reached = reachedAt >= 0;
    r.time_s = (reachedAt >= 0 ? reachedAt : t) - goalStart;
    r.final_distance_m = distanceToGoal();
    reachedAt = -1;
  };

  for (double t = 0; t < endT && goal < s.goals.size(); t = motion.t()) {
    // The IMU sample at t, then the frame at t (the order a rawlog keeps).
    if (estimated) {
      const sim::ImuMeasurement m =
          imu.measure(t, sim::imuKinematicsAt(motion.sample(), T_body_imu, w.imu.imu.gravity));
      auto obs = rawlog_tools::makeImuObservation(
          mrpt::Clock::fromDouble(stamp(t)), rawlog_tools::kImuLabel,
          std::array<double, 3>{m.gyro.x(), m.gyro.y(), m.gyro.z()},
          std::array<double, 3>{m.acc.x(), m.acc.y(), m.acc.z()});
      rawlog_tools::setImuPoseOnBody(*obs, T_body_imu);
      slam->onNewObservation(obs);
    }
    if (t >= nextFrame - 1e-9) {
      nextFrame += frameDt;
      const Eigen::Isometry3d T_world_camera = cameraPose();
      if (estimated) {
        sim::SimFrame frame;
        world.renderAt(t, T_world_camera, frameIndex, frame);
        if (feed) {
          std::vector<core::ObjectGroundTruthRow> rows;
          for (const auto& o : frame.objects)
            rows.push_back(sim::groundTruthRow(frameIndex, stamp(t), o));
          feed->add(rows);
        }
        const auto& k = world.camera();
        auto obs = rawlog_tools::makeRgbdObservation(rawlog_tools::simulatedRgbdFrame(
            mrpt::Clock::fromDouble(stamp(t)), frame.image.depth, world.maxRange(),
            {k.fx, k.fy, k.cx, k.cy}, images.storePixels(frame.image.rgb, ""),
            "closed-loop frame " + std::to_string(frameIndex)));
        rawlog_tools::setCameraPoseOnBody(*obs, T_body_camera);
        slam->onNewObservation(obs);
      } else {
        truthSource->update(t, stamp(t), T_world_camera);
      }
      ++frameIndex;

      // The record and the contacts, per frame.
      const Eigen::Isometry3d T_world_base = motion.sample().T_world_body;
      result.true_base.push_back({stamp(t), T_world_base});
      mrpt::math::TPose2D pose, odometry;
      mrpt::math::TTwist2D velocity;
      mrpt::system::TTimeStamp poseStamp;
      std::string frameId;
      if (adapter.getCurrentPoseAndSpeeds(pose, velocity, poseStamp, odometry, frameId))
        result.estimated_base.push_back(
            {stamp(t), T_world_start * planarPose(pose.x, pose.y, pose.phi)});
      const Eigen::Vector2d robotXy = T_world_base.translation().head<2>();
      const bool moving = std::abs(motion.speed()) > s.demo.moving_speed_m_s;
      for (const auto& agent : world.agents()) {
        const auto o = trueObject(agent, t, stamp(t));
        people << stamp(t) << ',' << o.id << ',' << o.category << ',' << o.pose.x << ',' << o.pose.y
               << ',' << o.velocity.x << ',' << o.velocity.y << ',' << o.moving << '\n';
        const double d = (Eigen::Vector2d(o.pose.x, o.pose.y) - robotXy).norm() - s.robot.radius_m -
                         s.demo.person_radius_m;
        peopleContacts.observe({t, o.id, motion.speed(), d, robotXy}, s.demo.collision_distance_m,
                               moving, result.collisions_people, result.contacts_people_robot_still,
                               result.min_distance_people_m, result.contacts);
      }
      staticContacts.observe(
          {t, 0, motion.speed(), statics.distance(robotXy) - s.robot.radius_m, robotXy},
          s.demo.collision_distance_m, moving, result.collisions_static,
          result.contacts_static_robot_still, result.min_distance_static_m, result.contacts);
    }

    if (t >= nextControl - 1e-9) {
      nextControl += controlDt;
      // The first goal after the wait, each next one once the robot has come to rest at the
      // last (as a robot with a list of goals does).
      const bool atRest = std::abs(motion.speed()) < 0.02 && std::abs(motion.turnRate()) < 0.02;
      if (!navigating && t >= s.demo.wait_s && atRest && goal < s.goals.size()) {
        navigateTo(goal);
        navigating = true;
        goalStart = t;
      }
      if (navigating) {
        navigator.navigationStep();
        if (distanceToGoal() <= s.demo.goal_tolerance_m && reachedAt < 0) reachedAt = t;
        const auto state = navigator.getCurrentState();
        // A goal ends when the navigator has stopped at it (by its own estimate) or the time is
        // up; it counts as reached when the true position came within the tolerance in time.
        if (state == mrpt::nav::CAbstractNavigator::IDLE ||
            t - goalStart > s.demo.goal_time_limit_s) {
          endGoal(t);
          navigator.cancel();
          motion.command(0, 0);
          navigating = false;
          ++goal;
        } else if (state == mrpt::nav::CAbstractNavigator::NAV_ERROR) {
          navigateTo(goal);  // blocked for a while: ask again until the time limit
        }
      }
      TopViewState v;
      v.t = t;
      v.goal = goal;
      v.robot = planarOf(motion.sample().T_world_body);
      if (!result.estimated_base.empty()) {
        v.estimated_valid = true;
        v.estimated = planarOf(result.estimated_base.back().T_world_body);
      }
      v.robot_radius = s.robot.radius_m;
      v.person_radius = s.demo.person_radius_m;
      for (const auto& agent : world.agents()) {
        const auto o = trueObject(agent, t, stamp(t));
        v.people.emplace_back(o.pose.x, o.pose.y);
      }
      // The sensed points are in the robot's frame as the adapter saw it (its estimate).
      const Eigen::Isometry3d T_world_sensed =
          v.estimated_valid ? planarPose(v.estimated) : planarPose(v.robot);
      for (const auto& p : robot.sensed())
        v.obstacles.push_back((T_world_sensed * Eigen::Vector3d(p.x(), p.y(), 0)).head<2>());
      view.add(v);
      if (settings.progress) settings.progress(t, goal);
    }
    motion.step(imuDt);
  }
  if (goal < s.goals.size() && navigating) endGoal(motion.t());  // the run's time ran out
  if (slam) slam->flush();
  result.duration_s = motion.t();
  result.frames = frameIndex;
  std::vector<bool> reached;
  for (const auto& g : result.goals) reached.push_back(g.reached);
  view.writeSummary((fs::path(settings.out_dir) / "top.png").string(), reached);
  std::ofstream contacts((fs::path(settings.out_dir) / "contacts.csv").string());
  contacts << "t,id,robot_speed,distance_m,robot_x,robot_y\n";
  for (const auto& c : result.contacts)
    contacts << c.t << ',' << c.id << ',' << c.robot_speed << ',' << c.distance_m << ','
             << c.robot.x() << ',' << c.robot.y() << '\n';
  core::writeTum((fs::path(settings.out_dir) / "trajectory_true.tum").string(), result.true_base);
  core::writeTum((fs::path(settings.out_dir) / "trajectory_estimated.tum").string(),
                 result.estimated_base);
  return result;
}

}  // namespace dynslam::navdemo
