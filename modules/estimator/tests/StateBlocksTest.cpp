#include <dynslam/estimator/StateBlocks.h>

#include <gtest/gtest.h>

using namespace dynslam::estimator;

TEST(StateBlocks, PoseBlockRoundTripsAndPlusMinusAreInverse) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = quaternionExp(Eigen::Vector3d(0.3, -0.2, 1.1)).toRotationMatrix();
  T.translation() = Eigen::Vector3d(1, -2, 3);
  double x[7];
  poseToBlock(T, x);
  EXPECT_TRUE(poseFromBlock(x).isApprox(T, 1e-12));

  PoseManifold m;
  const double delta[6] = {0.1, -0.2, 0.05, 0.02, -0.3, 0.1};
  double y[7], back[6];
  m.Plus(x, delta, y);
  m.Minus(y, x, back);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], delta[i], 1e-12) << i;
  // The rotation is perturbed on the right (body frame).
  const Eigen::Isometry3d Ty = poseFromBlock(y);
  const Eigen::Matrix3d expected =
      T.rotation() * quaternionExp(Eigen::Vector3d(0.02, -0.3, 0.1)).toRotationMatrix();
  EXPECT_TRUE(Ty.rotation().isApprox(expected, 1e-12));
}

TEST(StateBlocks, ExpOfSmallAndLargeAnglesIsAUnitQuaternion) {
  for (double a : {0.0, 1e-12, 1e-6, 0.5, 2.0}) {  // angles up to 3 rad < pi
    const Eigen::Quaterniond q = quaternionExp(Eigen::Vector3d(a, -a, 0.5 * a));
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
    EXPECT_NEAR(Eigen::AngleAxisd(q).angle(), a * 1.5, 1e-9);
  }
  EXPECT_TRUE(skew(Eigen::Vector3d(1, 2, 3)) * Eigen::Vector3d(4, 5, 6) ==
              Eigen::Vector3d(1, 2, 3).cross(Eigen::Vector3d(4, 5, 6)));
}
