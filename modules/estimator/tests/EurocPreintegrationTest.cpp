// Preintegration on real IMU data (issue 6): EuRoC V1_02, 40 s at 200 Hz, with the ground
// truth's states and biases. Between ground-truth states 0.5 s apart, preintegrating the raw
// samples with the ground-truth biases must predict the relative pose within 1 cm and 0.1 deg
// (median over the file).
#include <dynslam/core/Median.h>
#include <dynslam/estimator/imu/ImuPreintegration.h>
#include "EurocCsv.h"

#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

using namespace dynslam::estimator;
using namespace dynslam::estimator::testing;

TEST(EurocPreintegration, PredictsHalfSecondRelativePosesWithinOneCentimetreAndATenthDegree) {
  const std::string dir = dynslam::testing::sharedPath("data/euroc_v102_imu");
  if (dir.empty()) GTEST_SKIP() << "../shared/data/euroc_v102_imu is absent";
  const auto imu = readEurocCsv(dir + "/imu.csv");  // t[ns], gyro xyz, acc xyz
  const auto gt = readEurocCsv(dir + "/groundtruth.csv");  // t, p, q(w,x,y,z), v, bg, ba
  ASSERT_GT(imu.size(), 1000u);
  ASSERT_GT(gt.size(), 100u);
  std::map<long long, size_t> imuAt;
  for (size_t k = 0; k < imu.size(); ++k) imuAt[eurocNanoseconds(imu[k][0])] = k;
  std::map<long long, size_t> gtAt;
  for (size_t k = 0; k < gt.size(); ++k) gtAt[eurocNanoseconds(gt[k][0])] = k;

  const Eigen::Vector3d gravity(0, 0, -9.81);
  const long long window = 500'000'000;  // 0.5 s
  std::vector<double> positionErrors, rotationErrorsDeg;
  long long lastStart = -window;
  for (const auto& [ti, i] : gtAt) {
    if (ti - lastStart < window / 2) continue;  // windows every 0.25 s
    const auto j = gtAt.find(ti + window);
    const auto first = imuAt.find(ti);
    if (j == gtAt.end() || first == imuAt.end()) continue;
    const auto& a = gt[i];
    const auto& b = gt[j->second];
    const Eigen::Vector3d bg(a[11], a[12], a[13]), ba(a[14], a[15], a[16]);
    const auto& s0 = imu[first->second];
    ImuPreintegration pre(Eigen::Vector3d(s0[4], s0[5], s0[6]), Eigen::Vector3d(s0[1], s0[2], s0[3]),
                          ba, bg, ImuNoise{});
    size_t k = first->second + 1;
    for (; k < imu.size() && eurocNanoseconds(imu[k][0]) <= ti + window; ++k)
      pre.push(1e-9 * double(eurocNanoseconds(imu[k][0]) - eurocNanoseconds(imu[k - 1][0])),
               Eigen::Vector3d(imu[k][4], imu[k][5], imu[k][6]),
               Eigen::Vector3d(imu[k][1], imu[k][2], imu[k][3]));
    if (std::abs(pre.sumDt() - 0.5) > 1e-6) continue;  // an IMU gap: not comparable
    Eigen::Vector3d p, v;
    Eigen::Quaterniond q;
    pre.predict(Eigen::Vector3d(a[1], a[2], a[3]), Eigen::Quaterniond(a[4], a[5], a[6], a[7]),
                Eigen::Vector3d(a[8], a[9], a[10]), ba, bg, gravity, p, q, v);
    const Eigen::Quaterniond qb(b[4], b[5], b[6], b[7]);
    positionErrors.push_back((p - Eigen::Vector3d(b[1], b[2], b[3])).norm());
    rotationErrorsDeg.push_back(q.angularDistance(qb) * 180.0 / M_PI);
    lastStart = ti;
  }
  ASSERT_GT(positionErrors.size(), 50u) << "windows found in the file";
  const double pMed = dynslam::core::upperMedian(positionErrors),
               rMed = dynslam::core::upperMedian(rotationErrorsDeg);
  std::cout << positionErrors.size() << " windows of 0.5 s: median position error " << 100 * pMed
            << " cm, median rotation error " << rMed << " deg\n";
  EXPECT_LT(pMed, 0.01);
  EXPECT_LT(rMed, 0.1);
}
