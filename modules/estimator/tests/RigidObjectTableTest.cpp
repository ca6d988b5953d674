// RigidObjectTable: a later pose comes from the Umeyama fit of the known points, a point that
// moved away from the object starts again, and recentring moves the object frame without moving
// any world point.
#include <dynslam/estimator/RigidObjectTable.h>
#include <dynslam/estimator/StateBlocks.h>

#include <gtest/gtest.h>

using namespace dynslam::estimator;

namespace {

const PinholeCamera kCamera{500, 500, 320, 240};

/// Features of world points seen by a camera at the world origin (optical frame = world).
std::vector<RigidObjectFeature> see(const std::vector<Eigen::Vector3d>& world) {
  std::vector<RigidObjectFeature> out;
  for (size_t i = 0; i < world.size(); ++i)
    out.push_back({std::int64_t(i), kCamera.project(world[i]), world[i].z()});
  return out;
}

std::vector<Eigen::Vector3d> box(const Eigen::Isometry3d& L) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < 6; ++i)
    out.push_back(L * Eigen::Vector3d(0.2 * (i % 3) - 0.2, 0.25 * (i / 3), 0.1 * (i % 2)));
  return out;
}

Eigen::Isometry3d objectAt(double x) {
  Eigen::Isometry3d L = Eigen::Isometry3d::Identity();
  L.linear() = quaternionExp(Eigen::Vector3d(0, 0.1 * x, 0)).toRotationMatrix();
  L.translation() = Eigen::Vector3d(x, 0.1, 3.0);
  return L;
}

}  // namespace

TEST(RigidObjectTable, LaterPosesFitTheKnownPointsAndABrokenAwayPointStartsAgain) {
  RigidObjectTable table;
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  ASSERT_TRUE(table.observe(3, 0, see(box(objectAt(0))), I, kCamera, objectAt(0)));
  std::vector<Eigen::Vector3d> moved = box(objectAt(0.1));
  moved[4] += Eigen::Vector3d(0, 0.2, 0);  // an arm that swung away
  ASSERT_TRUE(table.observe(3, 1, see(moved), I, kCamera, std::nullopt));
  const RigidObject& o = table.all().at(3);
  const Eigen::Isometry3d L1 = poseFromBlock(o.poses.at(1).data());
  EXPECT_LT((L1.matrix() - objectAt(0.1).matrix()).norm(), 1e-6) << "Umeyama on the 5 others";
  for (const auto& [id, p] : o.points)
    EXPECT_EQ(p.observations.size(), id == 4 ? 1u : 2u) << "point " << id;
  // Too few features: not recorded.
  EXPECT_FALSE(table.observe(3, 2, {see(moved)[0], see(moved)[1]}, I, kCamera, std::nullopt));
  EXPECT_EQ(o.poses.count(2), 0u);
}

TEST(RigidObjectTable, RecentringMovesTheFrameNotTheWorldPoints) {
  RigidObjectTable table;
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  ASSERT_TRUE(table.observe(3, 0, see(box(objectAt(0))), I, kCamera, objectAt(0)));
  ASSERT_TRUE(table.observe(3, 1, see(box(objectAt(0.1))), I, kCamera, std::nullopt));
  auto worldPoints = [&] {
    std::vector<Eigen::Vector3d> out;
    for (const auto& [kf, L] : table.all().at(3).poses)
      for (const auto& [id, p] : table.all().at(3).points)
        out.push_back(poseFromBlock(L.data()) * Eigen::Vector3d(p.m_obj));
    return out;
  };
  const auto before = worldPoints();
  table.recentre(1);
  const auto after = worldPoints();
  ASSERT_EQ(before.size(), after.size());
  for (size_t i = 0; i < before.size(); ++i) EXPECT_LT((before[i] - after[i]).norm(), 1e-9);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& [id, p] : table.all().at(3).points) mean += Eigen::Vector3d(p.m_obj);
  EXPECT_LT(mean.norm() / 6, 1e-9) << "the origin is the centroid of the points seen";
  table.removeKeyframe(0);
  table.removeKeyframe(1);
  EXPECT_TRUE(table.all().empty()) << "an object with no keyframe left is gone";
}
