// Which PnP pose a frame between keyframes takes (FramePoseTracker.h, acceptPnpPose).
#include <dynslam/estimator/FramePoseTracker.h>

#include <gtest/gtest.h>

namespace dynslam::estimator {
namespace {

Eigen::Isometry3d shifted(const Eigen::Isometry3d& T, double dx, double yawDeg = 0) {
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.translate(Eigen::Vector3d(dx, 0, 0));
  step.rotate(Eigen::AngleAxisd(yawDeg * M_PI / 180, Eigen::Vector3d::UnitZ()));
  return T * step;
}

TEST(PnpPoseGate, AnImuPredictionHoldsThePoseTightly) {
  const Eigen::Isometry3d predicted = shifted(Eigen::Isometry3d::Identity(), 1.0);
  PnpPoseGate gate;
  gate.imu_max_m = 0.05;
  gate.imu_max_deg = 3;
  // A walker filling the view drags PnP 15 cm: refused against the IMU, taken without it.
  const Eigen::Isometry3d dragged = shifted(predicted, 0.15);
  EXPECT_FALSE(acceptPnpPose(dragged, predicted, true, predicted, gate));
  EXPECT_TRUE(acceptPnpPose(dragged, predicted, false, predicted, gate));
  EXPECT_TRUE(acceptPnpPose(shifted(predicted, 0.03, 1), predicted, true, predicted, gate));
  EXPECT_FALSE(acceptPnpPose(shifted(predicted, 0.0, 5), predicted, true, predicted, gate))
      << "turned more than 3 deg";
  gate.imu_max_m = gate.imu_max_deg = 0;  // off: the loose bounds only
  EXPECT_TRUE(acceptPnpPose(dragged, predicted, true, predicted, gate));
}

TEST(PnpPoseGate, WithoutTheImuALooseBoundAroundThePredictionOrTheLastPose) {
  const Eigen::Isometry3d last = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d extrapolated = shifted(last, 0.5);  // one bad step, extrapolated
  const PnpPoseGate gate;                                     // 0.3 m, 20 deg
  EXPECT_TRUE(acceptPnpPose(shifted(last, 0.02), extrapolated, false, last, gate))
      << "near the last pose, far from the prediction";
  EXPECT_FALSE(acceptPnpPose(shifted(last, 0.02), extrapolated, false, std::nullopt, gate));
  EXPECT_FALSE(acceptPnpPose(shifted(last, 1.0), last, false, last, gate));
  Eigen::Isometry3d broken = last;
  broken.translation().x() = std::nan("");
  EXPECT_FALSE(acceptPnpPose(broken, last, false, last, gate));
}

}  // namespace
}  // namespace dynslam::estimator
