// The street and market scenes: what the scenarios outdoor_street and market_crowd rely on.
// Small images and short runs keep it fast; the full-size scenarios are rendered by
// DynslamSim tests and the contact-sheet script.
#include "SmallScenario.h"

#include <dynslam/sim/ScenarioPaths.h>
#include <dynslam/sim/Simulator.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <map>

using namespace dynslam::sim;

namespace {

ScenarioOptions quarterSize(const std::string& scene, double duration) {
  ScenarioOptions o = dynslam::sim::testing::smallScenario(scene, duration, 5, 4);
  o.camera.path = "drive";
  return o;
}

ScenarioOptions street(double duration = 8) {
  ScenarioOptions o = quarterSize("street", duration);
  o.world.street_length = 60;
  o.camera.speed = 2.0;
  o.camera.height = 0.9;
  o.people.walkers = 10;
  o.people.standing = 3;
  o.cars.driving = 4;
  o.cars.parked = 5;
  o.gnss.enabled = true;
  o.noise.rgbd.max_range = 10;
  return o;
}

ScenarioOptions market(double duration = 8) {
  ScenarioOptions o = quarterSize("market", duration);
  o.world.room_size_x = 20;
  o.world.room_size_y = 12;
  o.world.room_height = 4;
  o.world.aisles = 4;
  o.camera.speed = 0.8;
  o.camera.height = 1.1;
  o.people.walkers = 12;
  o.people.standing = 4;
  return o;
}

}  // namespace

TEST(SimCar, BodyIsRigidAndSitsOnTheGround) {
  CarAppearance look;
  Eigen::Isometry3d a = Eigen::Isometry3d::Identity(), b = a;
  b.translation() = Eigen::Vector3d(3, -2, 0);
  b.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Mesh ma, mb;
  addCarMesh(ma, a, look, 9);
  addCarMesh(mb, b, look, 9);
  ASSERT_EQ(ma.size(), 108u);
  const Eigen::Isometry3d ca = carBodyPose(a, look), cb = carBodyPose(b, look);
  double worst = 0, lowest = 1e9, highest = -1e9;
  for (size_t i = 0; i < ma.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      worst = std::max(worst, (ca.inverse() * ma[i].p[k] - cb.inverse() * mb[i].p[k]).norm());
      lowest = std::min(lowest, ma[i].p[k].z());
      highest = std::max(highest, ma[i].p[k].z());
    }
  EXPECT_LT(worst, 1e-12) << "every vertex is fixed in the body frame";
  EXPECT_NEAR(lowest, 0.0, 1e-12) << "wheels touch the ground";
  EXPECT_NEAR(highest, look.height, 1e-12);
  for (const auto& t : ma) EXPECT_EQ(t.instance, 9);
}

TEST(SimStreet, CarsDriveAtTheirSpeedParkedCarsAndStandingPeopleStayPut) {
  const Simulator sim(street());
  std::map<std::string, int> moving, still;
  for (const auto& agent : sim.agents()) {
    const AgentState a = agentStateAt(agent, 2.0), b = agentStateAt(agent, 3.0);
    const double metres = (b.T_world_core.translation() - a.T_world_core.translation()).norm();
    const std::string kind = categoryName(agent.kind);
    if (a.moving) {
      ++moving[kind];
      // Straight stretches: the full speed; round the block's ends a little less.
      if (kind == "car") {
        EXPECT_NEAR(metres, 8.0, 1.0);
      }
    } else {
      ++still[kind];
      EXPECT_LT(metres, 1e-12);
    }
  }
  EXPECT_EQ(moving["car"], 4);
  EXPECT_EQ(still["car"], 5);
  EXPECT_EQ(moving["person"], 10);
  EXPECT_EQ(still["person"], 3);
}

TEST(SimStreet, RobotDrivesOnItsSidewalkWithGnssAndSeesCarsAndPeople) {
  const ScenarioOptions o = street();
  const Simulator sim(o);
  EXPECT_EQ(sim.gnss().size(), 81u) << "10 Hz over [0, 8] s";
  const double kerb = o.world.road_width / 2, facade = kerb + o.world.sidewalk_width;
  SimFrame f;
  std::map<std::string, int> seen;
  for (size_t i = 0; i < sim.frameCount(); ++i) {
    sim.renderFrame(i, f);
    const Eigen::Vector3d c = f.T_world_camera.translation();
    EXPECT_GT(c.y(), -facade + 0.5) << "frame " << i;
    EXPECT_LT(c.y(), -kerb - 0.5) << "frame " << i;
    EXPECT_NEAR(c.z(), 0.9, 0.1);
    for (const auto& obj : f.objects) {
      const cv::Mat mask = f.image.label == obj.id;
      EXPECT_EQ(cv::countNonZero(mask(obj.box)), cv::countNonZero(mask)) << "frame " << i;
      if (obj.visible_pixels > 50) ++seen[obj.category];
    }
  }
  EXPECT_GT(seen["car"], 0);
  EXPECT_GT(seen["person"], 0);
}

TEST(SimMarket, RouteStaysInTheAislesAndPeopleAreSeen) {
  const Simulator sim(market());
  SimFrame f;
  int seenPeople = 0;
  for (size_t i = 0; i < sim.frameCount(); ++i) {
    sim.renderFrame(i, f);
    // A shelf never fills the view: the aisle ahead stays open.
    const float ahead = f.image.depth.at<float>(f.image.depth.rows / 2, f.image.depth.cols / 2);
    const uint16_t who = f.image.label.at<uint16_t>(f.image.label.rows / 2, f.image.label.cols / 2);
    if (who == 0) {
      EXPECT_TRUE(ahead == 0 || ahead > 1.0) << "frame " << i << ": " << ahead;
    }
    for (const auto& obj : f.objects) seenPeople += obj.visible_pixels > 50;
  }
  EXPECT_GT(seenPeople, 5);
}

TEST(SimMarket, LongRunsDriveTheRouteThereAndBack) {
  const Simulator sim(market(400));  // 320 m at 0.8 m/s: more than the snake is long
  EXPECT_GE(sim.trajectory().endTime(), 400.0);
  const auto a = sim.trajectory().sample(100).velocity_world.norm();
  EXPECT_NEAR(a, 0.8, 0.05) << "still driving, not parked at the route's end";
}

TEST(SimMarket, HallTooSmallForItsAislesIsAnErrorNamingTheKeys) {
  ScenarioOptions o = market();
  o.world.aisles = 9;
  try {
    Simulator sim(o);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("room_size_y"), std::string::npos) << e.what();
  }
}

TEST(SimCorridor, RobotDrivesTheCentreLineAndMeetsPeopleHeadOn) {
  ScenarioOptions o = quarterSize("corridor", 10);
  o.world.room_size_x = 20;
  o.world.room_size_y = 2.4;
  o.camera.speed = 1.0;
  o.camera.height = 1.0;
  o.people.walkers = 4;
  o.people.standing = 1;
  const Simulator sim(o);
  SimFrame f;
  int seen = 0;
  for (size_t i = 0; i < sim.frameCount(); ++i) {
    sim.renderFrame(i, f);
    EXPECT_NEAR(f.T_world_camera.translation().y(), 0.0, 0.1) << "frame " << i;
    for (const auto& obj : f.objects) seen += obj.visible_pixels > 50;
  }
  EXPECT_GT(seen, 10);
  o.world.room_size_y = 1.2;
  EXPECT_THROW(Simulator{o}, std::invalid_argument) << "too narrow to pass anybody";
}

TEST(SimListedAgents, PeopleAndCarsOnPathsOfYourOwn) {
  ScenarioOptions o = dynslam::sim::testing::smallScenario("room", 2, 5, 1);
  o.people.walkers = 1;
  o.people.standing = 0;
  o.people.waypoints = "-1.5,0.5 1.5,0.5 | 0.3,-0.8";
  o.cars.waypoints = " 0,0 10,0 10,5 ";
  const Simulator sim(o);
  ASSERT_EQ(sim.agents().size(), 4u) << "one generated walker, two listed people, one car";
  const auto& walker = sim.agents()[1];
  EXPECT_EQ(walker.id, 2);
  EXPECT_TRUE(agentStateAt(walker, 0).T_world_core.translation().head<2>().isApprox(
      Eigen::Vector2d(-1.5, 0.5)));
  const AgentState standing = agentStateAt(sim.agents()[2], 1.0);
  EXPECT_FALSE(standing.moving);
  EXPECT_TRUE(standing.T_world_core.translation().head<2>().isApprox(Eigen::Vector2d(0.3, -0.8)));
  EXPECT_EQ(sim.agents()[3].kind, AgentKind::Car);
  EXPECT_TRUE(agentStateAt(sim.agents()[3], 1.0).moving);

  EXPECT_EQ(parseWaypointList("").size(), 0u);
  EXPECT_EQ(parseWaypointList("1,2 3,4|5,6")[1][0], Eigen::Vector2d(5, 6));
  for (const char* bad : {"1,2 3", "1;2", "1,2 | | 3,4", "1,2,3", "a,b"})
    EXPECT_THROW(parseWaypointList(bad), std::invalid_argument) << bad;
}
