#include <dynslam/sim/Person.h>

#include <gtest/gtest.h>

using namespace dynslam::sim;

TEST(SimWalkPath, WalksBackAndForthAtConstantSpeed) {
  const WalkPath path({{0, 0}, {3, 0}, {3, 4}}, 1.0);  // 7 m long
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
  EXPECT_TRUE(WalkPath({{1, 1}}, 1.0).standing());
}

TEST(SimPerson, TorsoIsRigidWhileLimbsSwing) {
  const WalkPath path({{0, 0}, {10, 0}}, 1.2);
  const PersonAppearance look;
  // Two gait phases a quarter cycle apart.
  const PersonPose a = personPoseAt(path, 0.3, 1.4), b = personPoseAt(path, 0.3 + 1.4 / 4 / 1.2, 1.4);
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
  const WalkPath path({{1, 2}}, 0.0);
  const PersonAppearance look;
  const auto a = personPoseAt(path, 0, 1.4), b = personPoseAt(path, 7.5, 1.4);
  EXPECT_FALSE(a.moving);
  EXPECT_TRUE(torsoPose(a, look).isApprox(torsoPose(b, look)));
}
