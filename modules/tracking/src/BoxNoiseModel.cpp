#include "dynslam/tracking/BoxNoiseModel.h"

#include <algorithm>
#include <cmath>

namespace dynslam::tracking {
namespace {

double sq(double x) { return x * x; }

/// Adds continuous white-acceleration noise q to the (value, rate) pair at (i, 5 + i).
void addWhiteAcceleration(BoxCovariance& Q, int i, double q, double dt) {
  Q(i, i) += q * dt * dt * dt / 3;
  Q(i, 5 + i) += q * dt * dt / 2;
  Q(5 + i, i) += q * dt * dt / 2;
  Q(5 + i, 5 + i) += q * dt;
}

}  // namespace

BoxMeasurementCovariance measurementNoise(const BoxNoiseParams& p, const BoxMeasurement& z) {
  BoxMeasurementCovariance R = BoxMeasurementCovariance::Zero();
  R(kU, kU) = R(kV, kV) = sq(p.meas_center_px);
  R(kS, kS) = sq(p.meas_area_rel * std::max(z(kS), 1.0));
  R(kD, kD) = z(kD) > 0 ? sq(p.meas_depth_rel * z(kD)) : kUnknownDepthVariance;
  R(kR, kR) = sq(p.meas_ratio);
  return R;
}

BoxCovariance processNoise(const BoxNoiseParams& p, const BoxState& x, double dt) {
  BoxCovariance Q = BoxCovariance::Zero();
  if (dt <= 0) return Q;
  addWhiteAcceleration(Q, kU, sq(p.accel_center_px), dt);
  addWhiteAcceleration(Q, kV, sq(p.accel_center_px), dt);
  addWhiteAcceleration(Q, kS, sq(p.accel_area_rel * std::max(x(kS), 1.0)), dt);
  addWhiteAcceleration(Q, kD, sq(p.accel_depth), dt);
  Q(kR, kR) = sq(p.ratio_walk) * dt;
  return Q;
}

BoxState initialState(const BoxMeasurement& z) {
  BoxState x = BoxState::Zero();
  x.head<5>() = z;
  if (!(z(kD) > 0)) x(kD) = 0;
  return x;
}

BoxCovariance initialCovariance(const BoxNoiseParams& p, const BoxMeasurement& z) {
  BoxCovariance P = BoxCovariance::Zero();
  P.topLeftCorner<5, 5>() = measurementNoise(p, z);
  P(kRateU, kRateU) = P(kRateV, kRateV) = sq(p.init_rate_center_px);
  P(kRateS, kRateS) = sq(p.init_rate_area_rel * std::max(z(kS), 1.0));
  P(kRateD, kRateD) = sq(p.init_rate_depth);
  return P;
}

}  // namespace dynslam::tracking
