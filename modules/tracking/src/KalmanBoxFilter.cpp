#include "dynslam/tracking/KalmanBoxFilter.h"

#include <Eigen/Cholesky>

#include <cmath>

namespace dynslam::tracking {

BoxMeasurement boxMeasurement(const cv::Rect2f& box, double depth) {
  BoxMeasurement z;
  z << box.x + 0.5 * box.width, box.y + 0.5 * box.height, double(box.width) * box.height, depth,
      box.height > 0 ? double(box.width) / box.height : 0.0;
  return z;
}

cv::Rect2f stateBox(const BoxState& x) {
  const double s = x(kS), r = x(kR);
  if (!(s > 0 && r > 0)) return {float(x(kU)), float(x(kV)), 0.f, 0.f};
  const double w = std::sqrt(s * r), h = std::sqrt(s / r);
  return {float(x(kU) - 0.5 * w), float(x(kV) - 0.5 * h), float(w), float(h)};
}

BoxCovariance transitionMatrix(double dt) {
  BoxCovariance A = BoxCovariance::Identity();
  for (int j : {kU, kV, kS, kD}) A(j, 5 + j) = dt;
  return A;
}

KalmanBoxFilter::KalmanBoxFilter(const BoxState& x0, const BoxCovariance& P0) : x_(x0), P_(P0) {}

void KalmanBoxFilter::predict(double dt, const BoxCovariance& Q) {
  const BoxCovariance A = transitionMatrix(dt);
  x_ = A * x_;
  P_ = A * P_ * A.transpose() + Q;
}

void KalmanBoxFilter::update(const BoxMeasurement& z, const BoxMeasurementCovariance& R) {
  // C = [I5 0]: C P- is the top five rows of P-, C P- C^T its top-left 5x5 block.
  const Eigen::Matrix<double, 5, 9> CP = P_.topRows<5>();
  const BoxMeasurementCovariance S = P_.topLeftCorner<5, 5>() + R;
  // K = P- C^T S^-1 = (S^-1 C P-)^T, as P- and S are symmetric.
  const Eigen::Matrix<double, 9, 5> K = S.llt().solve(CP).transpose();
  x_ += K * (z - x_.head<5>());
  P_ -= K * CP;                      // (I - K C) P-
  P_ = 0.5 * (P_ + P_.transpose());  // keep it symmetric against rounding
}

void KalmanBoxFilter::restartFrom(std::initializer_list<int> components, const BoxMeasurement& z,
                                  const BoxCovariance& P0) {
  auto restart = [&](int j) {
    P_.row(j).setZero();
    P_.col(j).setZero();
    P_(j, j) = P0(j, j);
  };
  for (int i : components) {
    x_(i) = z(i);
    restart(i);
    if (i == kR) continue;  // the aspect ratio has no rate
    x_(5 + i) = 0;
    restart(5 + i);
  }
}

}  // namespace dynslam::tracking
