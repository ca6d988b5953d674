// ObjectTrajectories: rigid-set motions given in camera coordinates, composed with the camera
// poses, reproduce the object's true world motion; a gap restarts the object at its centroid.
#include <dynslam/estimator/ObjectTrajectories.h>
#include <dynslam/estimator/StateBlocks.h>

#include <gtest/gtest.h>

using namespace dynslam;
using namespace dynslam::estimator;

namespace {

Eigen::Isometry3d pose(const Eigen::Vector3d& rotation, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = quaternionExp(rotation).toRotationMatrix();
  T.translation() = translation;
  return T;
}

Eigen::Isometry3d cameraAt(int k) { return pose({0, 0.02 * k, 0}, {0.05 * k, 0, 0.01 * k}); }
Eigen::Isometry3d objectAt(int k) {  // walks and turns
  return pose({0, 0, 0.05 * k}, {2 + 0.04 * k, 1, 3 - 0.02 * k});
}

core::Frame frameAt(int k) {
  core::Frame f;
  f.index = size_t(k);
  f.T_world_camera = cameraAt(k);
  if (k > 0) {
    // q = R p + t in camera coordinates of k-1 -> k for points fixed on the object.
    const Eigen::Isometry3d motion = cameraAt(k).inverse() * objectAt(k) * objectAt(k - 1).inverse() *
                                     cameraAt(k - 1);
    core::RigidSet set;
    set.object_id = 7;
    set.R = motion.rotation();
    set.t = motion.translation();
    set.virtual_centroid = cameraAt(k).inverse() * objectAt(k).translation();
    f.rigid_sets.push_back(set);
  }
  return f;
}

}  // namespace

TEST(ObjectTrajectories, FollowTheObjectsWorldMotion) {
  ObjectTrajectories trajectories;
  std::optional<Eigen::Isometry3d> first;
  for (int k = 0; k < 30; ++k) {
    core::Frame f = frameAt(k);
    trajectories.update(f);
    if (k == 0) {
      EXPECT_TRUE(f.object_poses.empty());
      continue;
    }
    ASSERT_EQ(f.object_poses.size(), 1u);
    EXPECT_EQ(f.object_poses[0].object_id, 7);
    const Eigen::Isometry3d& L = f.object_poses[0].T_world_object;
    if (!first) {
      first = L;
      EXPECT_LT((L.translation() - objectAt(k).translation()).norm(), 1e-9) << "starts at the centroid";
      continue;
    }
    // The object's frame differs from the true one by a fixed offset: compare motions.
    const Eigen::Isometry3d estimated = L * first->inverse();
    const Eigen::Isometry3d truth = objectAt(k) * objectAt(1).inverse();
    EXPECT_LT((estimated.matrix() - truth.matrix()).norm(), 1e-9) << "frame " << k;
  }
}

TEST(ObjectTrajectories, AGapRestartsAtTheNewCentroid) {
  ObjectTrajectories trajectories;
  for (int k : {0, 1, 2, 5, 6}) {
    core::Frame f = frameAt(k);
    trajectories.update(f);
    if (k == 5) {
      ASSERT_EQ(f.object_poses.size(), 1u);
      EXPECT_LT((f.object_poses[0].T_world_object.translation() - objectAt(5).translation()).norm(),
                1e-9);
      EXPECT_TRUE(f.object_poses[0].T_world_object.rotation().isApprox(Eigen::Matrix3d::Identity()));
    }
  }
}

TEST(ObjectTrajectories, TheWindowsEstimateReplacesTheComposedPoseAndIsComposedOn) {
  ObjectTrajectories trajectories;
  for (int k = 0; k < 3; ++k) {
    core::Frame f = frameAt(k);
    trajectories.update(f);
  }
  // Frame 3: the window estimates the object at its true pose; predict() gives what composing
  // alone would have given (the true motion from the composed frame-2 pose).
  core::Frame f3 = frameAt(3);
  const auto predicted = trajectories.predict(f3, cameraAt(3));
  ASSERT_EQ(predicted.count(7), 1u);
  trajectories.update(f3, {{7, objectAt(3)}});
  ASSERT_EQ(f3.object_poses.size(), 1u);
  EXPECT_TRUE(f3.object_poses[0].T_world_object.isApprox(objectAt(3), 1e-12));
  EXPECT_FALSE(predicted.at(7).isApprox(objectAt(3), 1e-3)) << "the composed frame differs";
  // Frame 4 composes the true motion onto the estimate: the true pose again.
  core::Frame f4 = frameAt(4);
  trajectories.update(f4);
  ASSERT_EQ(f4.object_poses.size(), 1u);
  EXPECT_LT((f4.object_poses[0].T_world_object.matrix() - objectAt(4).matrix()).norm(), 1e-9);
}
