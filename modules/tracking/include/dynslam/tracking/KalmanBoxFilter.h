#pragma once
// The linear Kalman filter of one tracked box (method.md section 2): state
// X = [u, v, s, d, r, du, dv, ds, dd] (box centre in pixels, box area in px^2, object depth in
// m, aspect ratio w/h held constant, and the rates of u, v, s, d per second), measurement
// Z = [u, v, s, d, r], C = [I5 0], A = I9 with A[j, 5 + j] = dt for j in {u, v, s, d}.
//
// Fixed-size Eigen matrices rather than mrpt::bayes::CKalmanFilterCapable: that class is built
// for one filter over a whole SLAM state (virtual callbacks for the transition and observation
// Jacobians, a growing list of landmarks, its own logger and timing per call), which is heavy
// for dozens of tiny 9-state filters created and dropped every second; its 1-D observation case
// does not even link in MRPT 2.5 (mrpt-notes.md). With C = [I5 0] the update is three block
// products on the stack, well under a microsecond.
//
// The filter is pure arithmetic: Q and R are given by the caller (BoxNoiseModel computes them
// from the ini's noise settings), so tests can check it against hand-computed values.
#include <Eigen/Core>
#include <opencv2/core/types.hpp>

#include <initializer_list>

namespace dynslam::tracking {

/// Indices into the state vector.
enum BoxStateIndex : int { kU = 0, kV, kS, kD, kR, kRateU, kRateV, kRateS, kRateD };

using BoxState = Eigen::Matrix<double, 9, 1>;
using BoxCovariance = Eigen::Matrix<double, 9, 9>;
using BoxMeasurement = Eigen::Matrix<double, 5, 1>;
using BoxMeasurementCovariance = Eigen::Matrix<double, 5, 5>;

/// Z = [u, v, s, d, r] of a box (x, y, w, h) with object depth `depth` (m).
BoxMeasurement boxMeasurement(const cv::Rect2f& box, double depth);

/// The box (x, y, w, h) of a state: w = sqrt(s r), h = sqrt(s / r). Empty (0 x 0 at the
/// centre) when s or r is not positive.
cv::Rect2f stateBox(const BoxState& x);

/// A = I9 with A[j, 5 + j] = dt for j in {u, v, s, d}.
BoxCovariance transitionMatrix(double dt);

class KalmanBoxFilter {
 public:
  /// Starts at `x0` with covariance `P0` (rates usually 0 with a large variance).
  KalmanBoxFilter(const BoxState& x0, const BoxCovariance& P0);

  /// X- = A X, P- = A P A^T + Q, with A = transitionMatrix(dt).
  void predict(double dt, const BoxCovariance& Q);

  /// K = P- C^T (C P- C^T + R)^-1, X = X- + K (Z - C X-), P = (I - K C) P-.
  void update(const BoxMeasurement& z, const BoxMeasurementCovariance& R);

  const BoxState& state() const { return x_; }
  const BoxCovariance& covariance() const { return P_; }
  /// The state's box (stateBox).
  cv::Rect2f box() const { return stateBox(x_); }
  /// Sets the area rate to 0, so the next prediction cannot make the area negative (a box that
  /// kept shrinking while coasting; SORT does the same).
  void stopAreaRate() { x_(kRateS) = 0; }
  /// Sets the depth rate to 0 (a coasting track holds its depth: a walker hidden for a second
  /// does not keep approaching at the rate it had when it disappeared).
  void stopDepthRate() { x_(kRateD) = 0; }
  /// Restarts the measured components `components` (of kU, kV, kS, kR) from the measurement:
  /// value = z, rate = 0, and their rows and columns of P from `P0` (a new track's covariance
  /// for z), uncorrelated with the rest. For measurements that do not follow the motion model,
  /// e.g. a box cut by the image border (KalmanBoxTracker::reset_at_border).
  void restartFrom(std::initializer_list<int> components, const BoxMeasurement& z,
                   const BoxCovariance& P0);

 private:
  BoxState x_;
  BoxCovariance P_;
};

}  // namespace dynslam::tracking
