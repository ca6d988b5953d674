#include <dynslam/sim/Person.h>

#include <gtest/gtest.h>

using namespace dynslam::sim;

TEST(SimFloorPath, WalksBackAndForthAtConstantSpeed) {
  const FloorPath path({{0, 0}, {3, 0}, {3, 4}}, 1.0);  // 7 m long
  Eigen::Vector2d xy;
  double heading = 0;
  path.at(0, xy, heading);
  EXPECT_NEAR((xy - Eigen::Vector2d(0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(heading, 0, 1e-9) << "walking along +x";
  path.at(5, xy, heading);
  EXPECT_NEAR((xy - Eigen::Vector2d(3, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR(heading, M_PI / 2, 1e-9) << "walking along +y";
  path.at(9, xy, heading);  // 7 m out, 2 m back
  EXPECT_NEAR((xy - Eigen::Vector2d(3, 2)).norm(), 0, 1e-12);
  EXPECT_NEAR(heading, -M_PI / 2, 1e-9) << "on the way back";
  path.at(14, xy, heading);
  EXPECT_NEAR(xy.norm(), 0, 1e-12) << "back at the start after twice the length";
  EXPECT_FALSE(path.standing());
  EXPECT_TRUE(FloorPath({{1, 1}}, 1.0).standing());
}

TEST(SimFloorPath, LoopsAndTurnsOverTheTurnLength) {
  // A 10 m x 4 m block driven round at 2 m/s, turning over 2 m at the corners.
  const FloorPath path({{0, 0}, {10, 0}, {10, 4}, {0, 4}}, 2.0, 0.0, FloorPath::Mode::Loop, 2.0);
  EXPECT_NEAR(path.length(), 28, 1e-12);
  Eigen::Vector2d xy;
  double heading = 0;
  path.at(2.5, xy, heading);  // 5 m along the first side: straight
  EXPECT_NEAR((xy - Eigen::Vector2d(5, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(heading, 0, 1e-12);
  path.at(5.0, xy, heading);  // at the corner: half way round it
  EXPECT_NEAR((xy - Eigen::Vector2d(10, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(heading, M_PI / 4, 1e-9);
  path.at(14.0 + 2.5, xy, heading);  // one loop later: where it was, no reversal
  EXPECT_NEAR((xy - Eigen::Vector2d(5, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR(heading, 0, 1e-9);
  path.at(13.0, xy, heading);  // 26 m: on the closing side (0, 4) -> (0, 0)
  EXPECT_NEAR((xy - Eigen::Vector2d(0, 2)).norm(), 0, 1e-9);
  EXPECT_NEAR(heading, -M_PI / 2, 1e-9);
  EXPECT_THROW(FloorPath({}, 1.0), std::invalid_argument);
  EXPECT_THROW(FloorPath({{0, 0}, {1, 0}}, 1.0, 0, FloorPath::Mode::Loop, 0.0),
               std::invalid_argument);
}

TEST(SimPerson, TorsoIsRigidWhileLimbsSwing) {
  const FloorPath path({{0, 0}, {10, 0}}, 1.2);
  const PersonAppearance look;
  // Two gait phases a quarter cycle apart.
  const PersonPose a = personPoseAt(path, 0.3, 1.4),
                   b = personPoseAt(path, 0.3 + 1.4 / 4 / 1.2, 1.4);
  EXPECT_TRUE(a.moving);
  Mesh ma, mb;
  addPersonMesh(ma, a, look, 7);
  addPersonMesh(mb, b, look, 7);
  ASSERT_EQ(ma.size(), mb.size());
  ASSERT_GE(ma.size(), 100u);
  const Eigen::Isometry3d ta = torsoPose(a, look), tb = torsoPose(b, look);
  // The first 24 triangles are torso and head: fixed in the torso frame.
  double torsoMotion = 0, limbMotion = 0;
  for (size_t i = 0; i < ma.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double d = (ta.inverse() * ma[i].p[k] - tb.inverse() * mb[i].p[k]).norm();
      (i < 24 ? torsoMotion : limbMotion) = std::max(i < 24 ? torsoMotion : limbMotion, d);
    }
  EXPECT_LT(torsoMotion, 1e-9);
  EXPECT_GT(limbMotion, 0.1) << "legs and arms move relative to the torso";
  for (const auto& t : ma) EXPECT_EQ(t.instance, 7);
  EXPECT_NEAR(ta.translation().z(), 1.2, 0.05);
}

TEST(SimPerson, StandingPersonDoesNotMove) {
  const FloorPath path({{1, 2}}, 0.0);
  const PersonAppearance look;
  const auto a = personPoseAt(path, 0, 1.4), b = personPoseAt(path, 7.5, 1.4);
  EXPECT_FALSE(a.moving);
  EXPECT_TRUE(torsoPose(a, look).isApprox(torsoPose(b, look)));
}
