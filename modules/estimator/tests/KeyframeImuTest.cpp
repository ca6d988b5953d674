// KeyframeImu: preintegrations cover exactly the intervals between keyframe stamps (the last
// sample held up to the stamp), and bad samples are errors naming the frame.
#include <dynslam/estimator/KeyframeImu.h>

#include <gtest/gtest.h>

using namespace dynslam::estimator;

namespace {

std::vector<dynslam::core::ImuSample> samples(double from, double to, double rate, double wz) {
  std::vector<dynslam::core::ImuSample> out;
  for (double t = from; t <= to + 1e-9; t += 1.0 / rate) {
    dynslam::core::ImuSample s;
    s.t = t;
    s.gyro = Eigen::Vector3d(0, 0, wz);
    s.acc = Eigen::Vector3d(0, 0, 9.81);
    s.has_gyro = s.has_acc = true;
    out.push_back(s);
  }
  return out;
}

}  // namespace

TEST(KeyframeImu, PreintegrationsSpanTheKeyframeIntervals) {
  KeyframeImu imu(ImuNoise{});
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  imu.addSamples(samples(0.0, 0.0301, 200, 1.0), 0);  // samples up to 0.030, frame at 0.0333
  EXPECT_EQ(imu.cutAt(0.0333, zero, zero), nullptr) << "the first keyframe has none";
  imu.addSamples(samples(0.035, 0.0666, 200, 1.0), 1);
  EXPECT_NEAR(imu.peekAt(0.068)->sumDt(), 0.068 - 0.0333, 1e-9) << "peek extends to its time";
  imu.addSamples(samples(0.070, 0.1, 200, 1.0), 2);
  const auto pre = imu.cutAt(0.1, zero, zero);
  ASSERT_TRUE(pre);
  EXPECT_NEAR(pre->sumDt(), 0.1 - 0.0333, 1e-9);
  // A constant 1 rad/s about z: the preintegrated rotation is exactly the interval's angle.
  EXPECT_NEAR(Eigen::AngleAxisd(pre->gamma()).angle(), 0.1 - 0.0333, 1e-9);
}

// While samples are missing (an IMU gap, which shows only once they resume) there is no
// prediction and no interval: holding the last sample over a second predicted a wrong motion,
// and the PnP gate then refused the right poses (bench/estimator_faults.sh: 2 window restarts).
TEST(KeyframeImu, NoPredictionOrIntervalPastTheLastSampleByMoreThanTheGap) {
  KeyframeImu imu(ImuNoise{}, 0.05);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  imu.addSamples(samples(0.0, 0.0301, 200, 1.0), 0);
  imu.cutAt(0.0333, zero, zero);
  imu.addSamples(samples(0.035, 0.1, 200, 1.0), 1);
  EXPECT_TRUE(imu.peekAt(0.12)) << "20 ms past the last sample: held";
  EXPECT_FALSE(imu.peekAt(0.2)) << "100 ms past: samples missing";
  EXPECT_FALSE(imu.cutAt(0.3, zero, zero)) << "a keyframe inside the gap closes no interval";
  EXPECT_FALSE(imu.peekAt(0.31)) << "nor does the next one predict";
  imu.addSamples(samples(1.0, 1.1, 200, 1.0), 2);  // the samples resume
  EXPECT_EQ(imu.gaps(), 1u);
  EXPECT_FALSE(imu.cutAt(1.1, zero, zero)) << "the interval over the gap is broken";
  imu.addSamples(samples(1.105, 1.2, 200, 1.0), 3);
  EXPECT_TRUE(imu.cutAt(1.2, zero, zero)) << "and the next one whole again";
}

TEST(KeyframeImu, NonFiniteAndOutOfOrderSamplesNameTheFrame) {
  KeyframeImu imu(ImuNoise{});
  auto s = samples(0.0, 0.01, 200, 0.0);
  imu.addSamples(s, 0);
  try {
    imu.addSamples(samples(0.005, 0.006, 200, 0.0), 7);
    FAIL() << "out-of-order sample accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("frame 7"), std::string::npos) << e.what();
  }
  auto bad = samples(0.02, 0.02, 200, 0.0);
  bad[0].gyro.x() = NAN;
  EXPECT_THROW(imu.addSamples(bad, 8), std::runtime_error);
}

TEST(KeyframeImu, APreintegrationLongerThanTheLimitIsDroppedAndTheNextStartsClean) {
  KeyframeImu imu(ImuNoise{}, KeyframeImu::kMaxGapS, 2.0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  imu.addSamples(samples(0.0, 0.1, 200, 0.5), 0);
  imu.cutAt(0.1, zero, zero);
  // Three seconds without a keyframe (tracking lost): past the 2 s limit it is dropped.
  imu.addSamples(samples(0.105, 1.9, 200, 0.5), 1);
  EXPECT_TRUE(imu.peekAt(1.9)) << "still inside the limit";
  imu.addSamples(samples(1.905, 3.1, 200, 0.5), 2);
  EXPECT_EQ(imu.peekAt(3.1), nullptr);
  EXPECT_EQ(imu.cutAt(3.1, zero, zero), nullptr) << "that keyframe pair gets no IMU factor";
  EXPECT_EQ(imu.overlong(), 1u);
  EXPECT_EQ(imu.gaps(), 0u) << "no sample was missing";
  imu.addSamples(samples(3.105, 3.4, 200, 0.5), 3);
  const auto next = imu.cutAt(3.4, zero, zero);
  ASSERT_TRUE(next) << "the next interval is whole again";
  EXPECT_NEAR(next->sumDt(), 0.3, 1e-9);
}

TEST(KeyframeImu, AKeyframePastTheLimitDropsAndCountsTheInterval) {
  KeyframeImu imu(ImuNoise{}, KeyframeImu::kMaxGapS, 2.0);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  imu.addSamples(samples(0.0, 0.1, 200, 0.5), 0);
  imu.cutAt(0.1, zero, zero);
  imu.addSamples(samples(0.105, 2.09, 200, 0.5), 1);  // the last one 1.99 s after the keyframe
  EXPECT_EQ(imu.overlong(), 0u);
  EXPECT_TRUE(imu.peekAt(2.09)) << "within the limit, no sample missing";
  EXPECT_EQ(imu.cutAt(2.12, zero, zero), nullptr) << "2.02 s, 0.03 s past the last sample";
  EXPECT_EQ(imu.overlong(), 1u);
}
