#pragma once
// The noise the box filter assumes (Q, R and the initial P), from a few physical settings.
//
// Why not SORT's constant matrices: SORT (Bewley et al. 2016) uses, per frame, R = diag(1, 1,
// 10, 10) and Q = diag(1, 1, 1, 1, 0.01, 0.01, 1e-4) on [u, v, s, r, du, dv, ds], with the area
// in px^2. A constant variance on the area is far too tight for a near person (80 000 px^2) and
// too loose for a far one (3 000 px^2), and per-frame values change meaning when frames are
// skipped (real-time mode predicts over whatever dt elapsed). Here the same structure is scaled:
// the area's noise is relative to the area, the depth's measurement noise relative to the depth,
// and the process noise is continuous white acceleration, so it depends on dt alone:
//   Q for (x, x') = q [[dt^3/3, dt^2/2], [dt^2/2, dt]]  with q = accel^2,
// per axis u, v, s (q scaled by s^2), d; the aspect ratio r walks with variance ratio_walk^2 dt.
// At 30 Hz the centre velocity's spread grows by accel_center_px / sqrt(30) = 18 px/s per frame
// (SORT: 0.1 px/frame = 3 px/s), the price of following people who stop and turn.
#include <dynslam/tracking/KalmanBoxFilter.h>

namespace dynslam::tracking {

struct BoxNoiseParams {
  // Measurement noise R (standard deviations).
  double meas_center_px = 3.0;   ///< box centre u, v, px (detector jitter)
  double meas_area_rel = 0.1;    ///< box area, relative to the measured area
  double meas_depth_rel = 0.05;  ///< object depth, relative to the measured depth
  double meas_ratio = 0.05;      ///< aspect ratio w/h (a walker's legs swing it by ~0.05)
  // Process noise Q (white acceleration densities, see above).
  double accel_center_px = 100.0;  ///< px/s^2/sqrt(Hz), of u and v
  double accel_area_rel = 1.0;     ///< 1/s^2/sqrt(Hz), of s relative to s
  double accel_depth = 1.0;        ///< m/s^2/sqrt(Hz), of d
  double ratio_walk = 0.1;         ///< 1/sqrt(s), random walk of r
  // Initial uncertainty of the rates (a new track's rates start at 0).
  double init_rate_center_px = 200.0;  ///< px/s
  double init_rate_area_rel = 1.0;     ///< 1/s, relative to the area
  double init_rate_depth = 1.5;        ///< m/s
};

/// Variance of d for a box with no depth measurement (measured depth <= 0) and of a new track
/// that has none yet: so large that such an update leaves d as it is and the first real depth
/// replaces it.
constexpr double kUnknownDepthVariance = 1e8;

/// R for measurement `z` (a depth z(kD) <= 0 means "not measured").
BoxMeasurementCovariance measurementNoise(const BoxNoiseParams& p, const BoxMeasurement& z);

/// Q for a prediction over `dt` seconds from state `x` (its area scales the area's noise).
BoxCovariance processNoise(const BoxNoiseParams& p, const BoxState& x, double dt);

/// A new track's state: the measurement, rates 0.
BoxState initialState(const BoxMeasurement& z);

/// A new track's covariance: R on the measured components, init_rate_* on the rates.
BoxCovariance initialCovariance(const BoxNoiseParams& p, const BoxMeasurement& z);

}  // namespace dynslam::tracking
