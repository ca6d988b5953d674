#include <dynslam/tracking/BoxNoiseModel.h>
#include <dynslam/tracking/KalmanBoxFilter.h>

#include <gtest/gtest.h>

#include <random>

using namespace dynslam::tracking;

TEST(TrackingKalmanBoxFilter, BoxAndMeasurementRoundTrip) {
  const cv::Rect2f box(100, 40, 50, 200);
  const BoxMeasurement z = boxMeasurement(box, 3.5);
  EXPECT_DOUBLE_EQ(z(kU), 125);
  EXPECT_DOUBLE_EQ(z(kV), 140);
  EXPECT_DOUBLE_EQ(z(kS), 10000);
  EXPECT_DOUBLE_EQ(z(kD), 3.5);
  EXPECT_DOUBLE_EQ(z(kR), 0.25);
  BoxState x = BoxState::Zero();
  x.head<5>() = z;
  const cv::Rect2f back = stateBox(x);
  EXPECT_NEAR(back.x, 100, 1e-4);
  EXPECT_NEAR(back.y, 40, 1e-4);
  EXPECT_NEAR(back.width, 50, 1e-4);
  EXPECT_NEAR(back.height, 200, 1e-4);
  x(kS) = -1;
  EXPECT_EQ(stateBox(x).area(), 0.f) << "a non-positive area is an empty box";
}

TEST(TrackingKalmanBoxFilter, TransitionMatrixIsTheMethods) {
  const BoxCovariance A = transitionMatrix(0.25);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c) {
      double expected = r == c ? 1.0 : 0.0;
      if (r < 4 && c == r + 5) expected = 0.25;  // u, v, s, d take their rates; r has none
      EXPECT_EQ(A(r, c), expected) << r << "," << c;
    }
}

TEST(TrackingKalmanBoxFilter, PredictMatchesHandComputedValues) {
  BoxState x0;
  x0 << 100, 50, 2000, 3, 0.5, 10, -5, 100, 0.2;
  BoxCovariance P0 = BoxCovariance::Zero();
  P0.diagonal() << 4, 4, 100, 0.01, 0.001, 9, 9, 400, 0.04;
  BoxCovariance Q = BoxCovariance::Zero();
  Q.diagonal() << 1, 1, 1, 1, 1, 1, 1, 1, 1;
  KalmanBoxFilter f(x0, P0);
  f.predict(0.1, Q);
  const BoxState& x = f.state();
  EXPECT_DOUBLE_EQ(x(kU), 101);
  EXPECT_DOUBLE_EQ(x(kV), 49.5);
  EXPECT_DOUBLE_EQ(x(kS), 2010);
  EXPECT_DOUBLE_EQ(x(kD), 3.02);
  EXPECT_DOUBLE_EQ(x(kR), 0.5);
  EXPECT_DOUBLE_EQ(x(kRateU), 10);
  const BoxCovariance& P = f.covariance();
  EXPECT_DOUBLE_EQ(P(kU, kU), 4 + 0.01 * 9 + 1);  // P + dt^2 P_rate + Q
  EXPECT_DOUBLE_EQ(P(kS, kS), 100 + 0.01 * 400 + 1);
  EXPECT_DOUBLE_EQ(P(kU, kRateU), 0.1 * 9);  // dt P_rate
  EXPECT_DOUBLE_EQ(P(kRateU, kU), 0.1 * 9);
  EXPECT_DOUBLE_EQ(P(kRateU, kRateU), 9 + 1);
  EXPECT_DOUBLE_EQ(P(kR, kR), 0.001 + 1);
  EXPECT_DOUBLE_EQ(P(kU, kV), 0);
}

TEST(TrackingKalmanBoxFilter, UpdateMatchesHandComputedValues) {
  // After predicting 1 s from P0 = diag(4 ..., rates 9) without process noise, the u block is
  // [[13, 9], [9, 9]]; with R_u = 1 the innovation variance is 14, K_u = 13/14, K_du = 9/14.
  BoxState x0 = BoxState::Zero();
  x0.head<5>() << 100, 50, 2000, 3, 0.5;
  BoxCovariance P0 = BoxCovariance::Identity() * 4;
  for (int i = kRateU; i <= kRateD; ++i) P0(i, i) = 9;
  KalmanBoxFilter f(x0, P0);
  f.predict(1.0, BoxCovariance::Zero());
  BoxMeasurement z;
  z << 114, 50, 2000, 3, 0.5;  // u measured 14 px right of the prediction, the rest on it
  BoxMeasurementCovariance R = BoxMeasurementCovariance::Identity();
  f.update(z, R);
  const BoxState& x = f.state();
  EXPECT_NEAR(x(kU), 100 + 13.0, 1e-9);
  EXPECT_NEAR(x(kRateU), 9.0, 1e-9);
  EXPECT_NEAR(x(kV), 50, 1e-9);
  EXPECT_NEAR(x(kRateV), 0, 1e-9);
  const BoxCovariance& P = f.covariance();
  EXPECT_NEAR(P(kU, kU), 13.0 / 14, 1e-9);     // 13 - 13^2/14
  EXPECT_NEAR(P(kU, kRateU), 9.0 / 14, 1e-9);  // 9 - 13*9/14
  EXPECT_NEAR(P(kRateU, kRateU), 9 - 81.0 / 14, 1e-9);
  EXPECT_NEAR(P(kR, kR), 4.0 / 5, 1e-9);  // no rate: 4 - 16/5
  EXPECT_TRUE(P.isApprox(P.transpose(), 1e-12));
}

TEST(TrackingKalmanBoxFilter, FollowsConstantVelocityAndTheRatesConverge) {
  // A box moving at constant rates, measured at 30 Hz with 2 px / 2 % noise.
  const double du = 60, dv = -30, ds = 800, dd = -0.4;  // px/s, px/s, px^2/s, m/s
  std::mt19937 rng(7);
  std::normal_distribution<double> pixel(0, 2), relative(0, 0.02);
  const BoxNoiseParams noise;
  const auto truthAt = [&](double t) {
    BoxMeasurement z;
    z << 200 + du * t, 240 + dv * t, 10000 + ds * t, 4 + dd * t, 0.4;
    return z;
  };
  const auto measured = [&](double t) {
    BoxMeasurement z = truthAt(t);
    z(kU) += pixel(rng);
    z(kV) += pixel(rng);
    z(kS) *= 1 + relative(rng);
    z(kD) *= 1 + relative(rng);
    return z;
  };
  const double dt = 1.0 / 30;
  BoxMeasurement z = measured(0);
  KalmanBoxFilter f(initialState(z), initialCovariance(noise, z));
  const double rateSigma0 = std::sqrt(f.covariance()(kRateU, kRateU));
  for (int k = 1; k <= 90; ++k) {
    f.predict(dt, processNoise(noise, f.state(), dt));
    z = measured(k * dt);
    f.update(z, measurementNoise(noise, z));
  }
  const BoxState& x = f.state();
  const BoxCovariance& P = f.covariance();
  const BoxMeasurement truth = truthAt(90 * dt);
  const BoxState rates = (BoxState() << 0, 0, 0, 0, 0, du, dv, ds, dd).finished();
  // Every component within 3 sigma of the filter's own uncertainty (it is consistent) ...
  for (int i : {kU, kV, kS, kD})
    EXPECT_LT(std::abs(x(i) - truth(i)), 3 * std::sqrt(P(i, i))) << "component " << i;
  for (int i : {kRateU, kRateV, kRateS, kRateD})
    EXPECT_LT(std::abs(x(i) - rates(i)), 3 * std::sqrt(P(i, i))) << "rate " << i;
  // ... and that uncertainty has shrunk from the initial guess to a useful level.
  EXPECT_LT(std::sqrt(P(kRateU, kRateU)), 0.2 * rateSigma0) << "rates converged";
  EXPECT_LT(std::sqrt(P(kRateU, kRateU)), 0.5 * du);
  EXPECT_LT(std::sqrt(P(kRateD, kRateD)), 0.5 * noise.init_rate_depth)
      << "the depth rate too (its measurement noise, 5 % of 4 m, is larger)";
  EXPECT_NEAR(x(kU), truth(kU), 3.0);
  EXPECT_NEAR(x(kD), truth(kD), 0.05);
}

TEST(TrackingBoxNoiseModel, ScalesWithAreaDepthAndTime) {
  const BoxNoiseParams p;
  BoxMeasurement z;
  z << 100, 100, 10000, 4, 0.4;
  const BoxMeasurementCovariance R = measurementNoise(p, z);
  EXPECT_DOUBLE_EQ(R(kU, kU), 9);
  EXPECT_DOUBLE_EQ(R(kS, kS), 1000.0 * 1000.0);  // 10 % of the area
  EXPECT_DOUBLE_EQ(R(kD, kD), 0.2 * 0.2);        // 5 % of the depth
  z(kD) = 0;
  EXPECT_DOUBLE_EQ(measurementNoise(p, z)(kD, kD), kUnknownDepthVariance);
  const BoxState x = initialState(z);
  const BoxCovariance Q1 = processNoise(p, x, 0.1), Q2 = processNoise(p, x, 0.2);
  EXPECT_NEAR(Q2(kRateU, kRateU), 2 * Q1(kRateU, kRateU), 1e-9) << "velocity noise ~ dt";
  EXPECT_NEAR(Q2(kU, kU), 8 * Q1(kU, kU), 1e-9) << "position noise ~ dt^3";
  EXPECT_TRUE(processNoise(p, x, 0).isZero());
}
