// ImuInitializer on real IMU data (issue 6 item 5): EuRoC V1_02, 200 Hz IMU and ground truth.
// The ground-truth poses of 10 keyframes 0.3 s apart stand for the RGB-D odometry, in a
// 'visual' world turned from the gravity-aligned one by a known arbitrary rotation; the raw IMU
// between them is preintegrated with zero bias. The initializer must find the ground truth's
// gyro bias (median within 0.002 rad/s) and the gravity direction (median within 1 deg; the
// test says why not every window). One window every second over the IMU file's 40 s.
#include <dynslam/core/Median.h>
#include <dynslam/estimator/ImuInitializer.h>
#include <dynslam/estimator/StateBlocks.h>
#include "EurocCsv.h"

#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

namespace {

// The same reader as EurocPreintegrationTest.cpp (kept local: that file is another author's).

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

struct WindowResult {
  bool accepted;
  double bias_error, gravity_deg, velocity_error;  // rad/s, deg, m/s (worst keyframe)
};

/// Runs the initializer on one window every second; with removeTrueAccBias the preintegrations
/// are linearised at the ground truth's accelerometer bias (which the initializer does not
/// estimate) instead of zero.
std::vector<WindowResult> runWindows(const std::string& dir, bool removeTrueAccBias) {
  const auto imu = readEurocCsv(dir + "/imu.csv");         // t[ns], gyro xyz, acc xyz
  const auto gt = readEurocCsv(dir + "/groundtruth.csv");  // t, p, q(w,x,y,z), v, bg, ba
  std::vector<WindowResult> results;
  if (imu.size() < 1000 || gt.size() < 100) return results;
  std::map<long long, size_t> imuAt;
  for (size_t k = 0; k < imu.size(); ++k) imuAt[eurocNanoseconds(imu[k][0])] = k;
  std::map<long long, size_t> gtAt;
  for (size_t k = 0; k < gt.size(); ++k) gtAt[eurocNanoseconds(gt[k][0])] = k;

  // The 'visual' world: the ground truth's frame turned and moved by an arbitrary known pose.
  Eigen::Isometry3d T_visual_gt = Eigen::Isometry3d::Identity();
  T_visual_gt.linear() = quaternionExp(Eigen::Vector3d(0.7, -1.9, 0.4)).toRotationMatrix();
  T_visual_gt.translation() = Eigen::Vector3d(3, -1, 2);
  const Eigen::Vector3d gravityVisual = T_visual_gt.linear() * Eigen::Vector3d(0, 0, -9.81);

  ImuNoise adis16448;  // EuRoC's sensor.yaml (the preintegration covariance weights the scale)
  adis16448.acc_noise = 2.0e-3;
  adis16448.gyro_noise = 1.6968e-4;
  adis16448.acc_random_walk = 3.0e-3;
  adis16448.gyro_random_walk = 1.9393e-5;

  constexpr int kKeyframes = 10;
  const long long spacing = 300'000'000, stride = 1'000'000'000;  // 0.3 s, windows every 1 s
  for (long long start = gtAt.begin()->first;; start += stride) {
    std::vector<ImuInitKeyframe> keyframes;
    std::vector<std::unique_ptr<ImuPreintegration>> pre;
    std::vector<ImuPreintegration*> pointers;
    std::vector<Eigen::Vector3d> trueVelocities;
    bool complete = true;
    for (int k = 0; k < kKeyframes && complete; ++k) {
      const long long t = start + k * spacing;
      const auto g = gtAt.find(t);
      const auto s = imuAt.find(t);
      if (g == gtAt.end() || s == imuAt.end()) {
        complete = false;
        break;
      }
      const auto& row = gt[g->second];
      Eigen::Isometry3d T_gt_body = Eigen::Isometry3d::Identity();
      T_gt_body.linear() = Eigen::Quaterniond(row[4], row[5], row[6], row[7]).toRotationMatrix();
      T_gt_body.translation() = Eigen::Vector3d(row[1], row[2], row[3]);
      keyframes.push_back({1e-9 * double(t - start), T_visual_gt * T_gt_body});
      trueVelocities.push_back(T_visual_gt.linear() * Eigen::Vector3d(row[8], row[9], row[10]));
      if (k + 1 == kKeyframes) break;
      const auto& s0 = imu[s->second];
      auto p = std::make_unique<ImuPreintegration>(
          Eigen::Vector3d(s0[4], s0[5], s0[6]), Eigen::Vector3d(s0[1], s0[2], s0[3]),
          removeTrueAccBias ? Eigen::Vector3d(row[14], row[15], row[16]) : Eigen::Vector3d::Zero(),
          Eigen::Vector3d::Zero(), adis16448);
      for (size_t j = s->second + 1; j < imu.size() && eurocNanoseconds(imu[j][0]) <= t + spacing; ++j)
        p->push(1e-9 * double(eurocNanoseconds(imu[j][0]) - eurocNanoseconds(imu[j - 1][0])),
                Eigen::Vector3d(imu[j][4], imu[j][5], imu[j][6]),
                Eigen::Vector3d(imu[j][1], imu[j][2], imu[j][3]));
      pointers.push_back(p.get());
      pre.push_back(std::move(p));
    }
    if (!complete) {
      if (gtAt.lower_bound(start + kKeyframes * spacing) == gtAt.end()) break;  // end of file
      continue;  // a gap in the ground truth or the IMU
    }
    const auto& first = gt[gtAt.at(start)];
    const Eigen::Vector3d trueBias(first[11], first[12], first[13]);
    const ImuInitialization r = initializeImu(keyframes, pointers);
    const double biasError = (r.gyro_bias - trueBias).norm();
    const double gravityDeg = angleDeg(r.gravity_world, gravityVisual);
    double velocityError = 0;
    for (int k = 0; k < kKeyframes; ++k)
      velocityError = std::max(velocityError, (r.velocities_world[k] - trueVelocities[k]).norm());
    if (!removeTrueAccBias)  // one line per window, for the zero-bias run only
      std::cout << "window at +" << 1e-9 * double(start - gtAt.begin()->first)
                << " s: " << (r.success ? "accepted" : "refused (" + r.reason + ")")
                << "; gyro bias error " << biasError << " rad/s, gravity " << gravityDeg
                << " deg, worst velocity " << velocityError << " m/s, acceleration RMS "
                << r.acceleration_rms << " m/s^2, visual scale " << r.visual_scale << " +- "
                << r.visual_scale_sigma << ", residual RMS " << r.position_rms << " m / "
                << r.velocity_rms << " m/s\n";
    results.push_back({r.success, biasError, gravityDeg, velocityError});
  }
  return results;
}

}  // namespace

// The gravity direction carries the accelerometer bias the initializer does not estimate
// (header): EuRoC's is 0.14 m/s^2 across the up axis, a 0.8 deg tilt. Hence the 1 deg bound is
// on the median, with a 1.5 deg bound on every window; a second run with the true bias removed
// shows that the rest is small. The gyro bias: the ground truth's orientations are good to
// ~0.05 deg (EurocPreintegrationTest), which over 0.3 s intervals moves the bias by ~0.001
// rad/s and, in a few windows, beyond 0.003.
TEST(EurocImuInitializer, FindsGyroBiasAndGravityDirection) {
  DYNSLAM_REQUIRE_SHARED(dir, "data/euroc_v102_imu");
  for (bool removeTrueAccBias : {false, true}) {
    const std::vector<WindowResult> results = runWindows(dir, removeTrueAccBias);
    ASSERT_GE(results.size(), 10u);
    std::vector<double> bias, gravity, velocity;
    for (const WindowResult& w : results) {
      if (!w.accepted) continue;
      bias.push_back(w.bias_error);
      gravity.push_back(w.gravity_deg);
      velocity.push_back(w.velocity_error);
    }
    ASSERT_GE(bias.size(), results.size() * 8 / 10) << "windows accepted";
    const double worstBias = *std::max_element(bias.begin(), bias.end());
    const double worstGravity = *std::max_element(gravity.begin(), gravity.end());
    std::cout << (removeTrueAccBias ? "true accelerometer bias removed: " : "zero bias: ")
              << bias.size() << " of " << results.size()
              << " windows accepted; gyro bias error median " << dynslam::core::upperMedian(bias)
              << ", worst " << worstBias << " rad/s; gravity direction error median "
              << dynslam::core::upperMedian(gravity) << ", worst " << worstGravity
              << " deg; worst-keyframe velocity error median "
              << dynslam::core::upperMedian(velocity) << " m/s\n";
    EXPECT_LT(dynslam::core::upperMedian(bias), 0.002);
    EXPECT_LT(worstBias, 0.004);
    if (removeTrueAccBias) {
      EXPECT_LT(worstGravity, 0.5);
    } else {
      EXPECT_LT(dynslam::core::upperMedian(gravity), 1.0);
      EXPECT_LT(worstGravity, 1.5);
    }
  }
}
