// Contract of the adaptive rigid point set (method.md section 4, paper Fig. 5): a point that
// starts moving rigidly with the set joins it (P2), a member that breaks away leaves it (P1),
// and the virtual centroid is carried with the estimated motion, unmoved by members coming and
// going.
#include <dynslam/frontend/RigidPointSet.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace dynslam::frontend {
namespace {

bool contains(const std::vector<std::int64_t>& v, std::int64_t id) {
  return std::find(v.begin(), v.end(), id) != v.end();
}

/// A torso of 12 points turning 2 deg and moving 5 cm per frame, a "joiner" (id 100) that
/// stands still for 4 frames and then moves with the torso, a "leaver" (id 101) that moves with
/// the torso until frame 5 and then swings off by 10 cm per frame, and two limb points (ids 200,
/// 201) that move on their own.
struct Body {
  RigidMotion step{Eigen::AngleAxisd(2 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                   Eigen::Vector3d(0.05, 0.0, 0.01)};
  std::map<std::int64_t, Eigen::Vector3d> points;
  int frame = 0;

  Body() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (int i = 0; i < 12; ++i) points[i] = Eigen::Vector3d(u(rng), 2 * u(rng), 3 + u(rng) / 2);
    points[100] = Eigen::Vector3d(0.3, 0.0, 3.0);
    points[101] = Eigen::Vector3d(-0.1, 0.1, 3.05);
    points[200] = Eigen::Vector3d(0.2, 0.6, 3.0);
    points[201] = Eigen::Vector3d(-0.2, 0.6, 3.0);
  }

  /// Moves one frame on; the pairs of the move.
  std::vector<PointPair> advance() {
    std::vector<PointPair> pairs;
    for (auto& [id, P] : points) {
      Eigen::Vector3d next = step.apply(P);
      if (id == 100 && frame < 4) next = P;  // still, then with the torso
      if (id == 101 && frame >= 5) next = step.apply(P) + Eigen::Vector3d(0, 0.1, 0);
      if (id == 200) next = P + Eigen::Vector3d(0, 0.08 * ((frame % 2) ? 1 : -1), 0.02);
      if (id == 201) next = P + Eigen::Vector3d(0.1, -0.05, 0);
      pairs.push_back({id, P, next});
      P = next;
    }
    ++frame;
    return pairs;
  }
};

TEST(AdaptiveRigidPointSet, AdmitsAJoinerDropsALeaverAndCarriesTheVirtualCentroid) {
  Body body;
  AdaptiveRigidPointSet set;  // the method's settings: 4 pairs, 100 iterations, tau 0.03 m
  ASSERT_TRUE(set.update(body.advance()));
  EXPECT_TRUE(set.lastUpdate().created);
  EXPECT_EQ(set.members().size(), 13u);  // the torso and the leaver, nothing else
  EXPECT_FALSE(contains(set.members(), 100));
  EXPECT_TRUE(contains(set.members(), 101));
  EXPECT_FALSE(contains(set.members(), 200));
  EXPECT_FALSE(contains(set.members(), 201));

  // The virtual centroid starts as the members' centroid in this frame.
  Eigen::Vector3d expected = Eigen::Vector3d::Zero();
  for (auto id : set.members()) expected += body.points[id];
  expected /= double(set.members().size());
  EXPECT_LT((set.virtualCentroid() - expected).norm(), 1e-9);

  bool joined = false, left = false;
  for (int k = 1; k < 8; ++k) {
    ASSERT_TRUE(set.update(body.advance())) << "frame " << k;
    EXPECT_FALSE(set.lastUpdate().created) << "frame " << k;
    expected = body.step.apply(expected);
    // The motion is the torso's, and the virtual centroid follows it exactly, also in the
    // frames in which a member joins or leaves.
    EXPECT_LT((set.motion().R - body.step.R).norm(), 1e-9) << "frame " << k;
    EXPECT_LT((set.motion().t - body.step.t).norm(), 1e-9) << "frame " << k;
    EXPECT_LT((set.virtualCentroid() - expected).norm(), 1e-9) << "frame " << k;
    joined |= contains(set.lastUpdate().joined, 100);
    left |= contains(set.lastUpdate().left, 101);
    EXPECT_FALSE(contains(set.members(), 200));
    EXPECT_FALSE(contains(set.members(), 201));
  }
  EXPECT_TRUE(joined);  // it moved with the torso from frame 4 on
  EXPECT_TRUE(left);    // it broke away at frame 5
  EXPECT_TRUE(contains(set.members(), 100));
  EXPECT_FALSE(contains(set.members(), 101));

  const core::RigidSet out = set.toRigidSet(7);
  EXPECT_EQ(out.object_id, 7);
  EXPECT_EQ(out.members, set.members());
  EXPECT_EQ(out.virtual_centroid, set.virtualCentroid());
}

TEST(AdaptiveRigidPointSet, NoSetWithoutEnoughRigidPoints) {
  // Five points each moving its own way: no four of them share a motion within 3 cm.
  std::vector<PointPair> pairs;
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d p(0.3 * i, 0.1 * i * i, 3.0);
    pairs.push_back({i, p, p + Eigen::Vector3d(0.2 * i, -0.15 * i * (i % 2), 0.1 * (i % 3))});
  }
  AdaptiveRigidPointSet set;
  EXPECT_FALSE(set.update(pairs));
  EXPECT_FALSE(set.exists());
}

}  // namespace
}  // namespace dynslam::frontend
