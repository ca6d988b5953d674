#include <dynslam/sim/TrajectoryPaths.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace dynslam::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// The fastest phase advance per knot the helpers accept: 4 knots per period.
constexpr double kMaxPhasePerKnot = kPi / 2 + 1e-12;

/// How much a uniform cubic B-spline shrinks a sinusoid that advances `phase_per_knot` rad per
/// control point, at the knots: (c[j-1] + 4 c[j] + c[j+1]) / 6 of a sampled e^{i w t}.
double knotAttenuation(double phase_per_knot) {
  return (4.0 + 2.0 * std::cos(phase_per_knot)) / 6.0;
}

/// Control count so the curve, starting at t = 0, covers [0, duration].
std::size_t controlCountFor(double duration, double knot_interval) {
  return static_cast<std::size_t>(std::ceil(duration / knot_interval - 1e-9)) + 3;
}

void requirePositive(double value, const char* what, const char* function) {
  if (!(value > 0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string(function) + ": " + what +
                                " must be positive and finite, got " + std::to_string(value));
  }
}

/// A polyline parametrised by arc length.
class Polyline {
 public:
  explicit Polyline(const std::vector<Eigen::Vector2d>& waypoints) {
    for (const auto& p : waypoints) {
      if (!p.allFinite()) throw std::invalid_argument("makeDrivePath: a waypoint is not finite");
      if (!points_.empty() && (p - points_.back()).norm() < 1e-9) continue;  // duplicates
      cumulative_.push_back(points_.empty() ? 0.0
                                            : cumulative_.back() + (p - points_.back()).norm());
      points_.push_back(p);
    }
    if (points_.size() < 2) {
      throw std::invalid_argument("makeDrivePath: needs at least 2 distinct waypoints, got " +
                                  std::to_string(points_.size()));
    }
  }
  double length() const { return cumulative_.back(); }
  Eigen::Vector2d pointAt(double s) const {
    const std::size_t i = segmentAt(s);
    const double f = (s - cumulative_[i]) / (cumulative_[i + 1] - cumulative_[i]);
    return points_[i] + std::clamp(f, 0.0, 1.0) * (points_[i + 1] - points_[i]);
  }
  double headingAt(double s) const {
    const std::size_t i = segmentAt(s);
    const Eigen::Vector2d d = points_[i + 1] - points_[i];
    return std::atan2(d.y(), d.x());
  }

 private:
  std::size_t segmentAt(double s) const {
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cumulative_.begin(), 1));
    return std::min(i - 1, points_.size() - 2);
  }
  std::vector<Eigen::Vector2d> points_;
  std::vector<double> cumulative_;
};

/// Distance travelled at t for a trapezoid-like speed profile whose ramps are smoothsteps
/// (speed * (3x^2 - 2x^3)), so the acceleration is continuous.
class SpeedProfile {
 public:
  SpeedProfile(double length, double speed, double ramp)
      : length_(length), speed_(speed), ramp_(ramp), duration_(length / speed + ramp) {}
  double duration() const { return duration_; }
  double distanceAt(double t) const {
    t = std::clamp(t, 0.0, duration_);
    if (ramp_ <= 0) return std::min(speed_ * t, length_);
    if (t < ramp_) return rampDistance(t / ramp_);
    if (t > duration_ - ramp_) return length_ - rampDistance((duration_ - t) / ramp_);
    return speed_ * ramp_ / 2 + speed_ * (t - ramp_);
  }

 private:
  /// Integral of the smoothstep speed over the first x * ramp seconds.
  double rampDistance(double x) const { return speed_ * ramp_ * (x * x * x - x * x * x * x / 2); }
  double length_, speed_, ramp_, duration_;
};

/// Turns values sampled at the control times into controls whose spline passes through them:
/// values[1..n-2] become the solution of c[i-1] + 4 c[i] + c[i+1] = 6 y[i] (the curve at knot
/// i - 1), with values[0] and values[n-1] kept as the end controls. The system is tridiagonal and
/// diagonally dominant, so the Thomas algorithm is stable.
void interpolateThroughKnots(std::vector<double>& values) {
  const std::size_t n = values.size();
  if (n < 3) return;
  std::vector<double> c_prime(n, 0.0), d_prime(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    double rhs = 6 * values[i];
    if (i == 1) rhs -= values[0];
    if (i + 2 == n) rhs -= values[n - 1];
    const double pivot = 4 - (i == 1 ? 0.0 : c_prime[i - 1]);
    c_prime[i] = 1 / pivot;
    d_prime[i] = (rhs - (i == 1 ? 0.0 : d_prime[i - 1])) / pivot;
  }
  values[n - 2] = d_prime[n - 2];
  for (std::size_t i = n - 2; i-- > 1;) values[i] = d_prime[i] - c_prime[i] * values[i + 1];
}

}  // namespace

void unwrapAngles(std::vector<double>& angles) {
  for (std::size_t i = 1; i < angles.size(); ++i) {
    angles[i] = angles[i - 1] + std::remainder(angles[i] - angles[i - 1], 2 * kPi);
  }
}

SplineTrajectory makeOrbit(const Eigen::Vector3d& center, double radius, double height,
                           double period_s, double duration_s, const Eigen::Vector3d& look_at,
                           double bob_amplitude, double knot_interval, double bob_frequency_hz) {
  constexpr const char* kFn = "makeOrbit";
  requirePositive(radius, "radius", kFn);
  requirePositive(duration_s, "duration", kFn);
  requirePositive(knot_interval, "knot_interval", kFn);
  if (period_s == 0 || !std::isfinite(period_s)) {
    throw std::invalid_argument("makeOrbit: period_s must be non-zero and finite");
  }
  if (!(bob_frequency_hz >= 0) || !std::isfinite(bob_amplitude)) {
    throw std::invalid_argument("makeOrbit: bob_frequency_hz must be >= 0, amplitude finite");
  }
  const double turn_phase = 2 * kPi * knot_interval / period_s;
  const double bob_phase = 2 * kPi * bob_frequency_hz * knot_interval;
  if (std::abs(turn_phase) > kMaxPhasePerKnot) {
    throw std::invalid_argument("makeOrbit: fewer than 4 knots per turn (period " +
                                std::to_string(period_s) + " s, knot interval " +
                                std::to_string(knot_interval) + " s); shorten the knot interval");
  }
  if (bob_amplitude != 0 && bob_phase > kMaxPhasePerKnot) {
    throw std::invalid_argument("makeOrbit: fewer than 4 knots per bob period (" +
                                std::to_string(bob_frequency_hz) + " Hz, knot interval " +
                                std::to_string(knot_interval) +
                                " s); lower bob_frequency_hz or shorten the knot interval");
  }
  const double radius_gain = 1.0 / knotAttenuation(turn_phase);
  const double bob_gain = 1.0 / knotAttenuation(bob_phase);

  const std::size_t n = controlCountFor(duration_s, knot_interval);
  std::vector<Eigen::Vector3d> positions(n), ypr(n);
  std::vector<double> yaws(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (static_cast<double>(i) - 1.0) * knot_interval;
    const double theta = 2 * kPi * t / period_s;
    const double bob = bob_amplitude * std::sin(2 * kPi * bob_frequency_hz * t);
    const Eigen::Vector3d ring(std::cos(theta), std::sin(theta), 0);
    const Eigen::Vector3d intended = center + radius * ring + Eigen::Vector3d(0, 0, height + bob);
    positions[i] =
        center + radius_gain * radius * ring + Eigen::Vector3d(0, 0, height + bob_gain * bob);
    // Orientation from the intended (on-circle) position: the direction to look_at.
    const Eigen::Vector3d to_target = look_at - intended;
    const double horizontal = to_target.head<2>().norm();
    if (horizontal < 1e-9 * std::max(1.0, radius)) {
      throw std::invalid_argument("makeOrbit: look_at lies on the camera's vertical line");
    }
    yaws[i] = std::atan2(to_target.y(), to_target.x());
    ypr[i] = Eigen::Vector3d(0, std::atan2(-to_target.z(), horizontal), 0);  // + pitch: nose down
  }
  unwrapAngles(yaws);
  for (std::size_t i = 0; i < n; ++i) ypr[i][0] = yaws[i];
  return SplineTrajectory(std::move(positions), std::move(ypr), knot_interval, 0.0);
}

SplineTrajectory makeDrivePath(const std::vector<Eigen::Vector2d>& waypoints_xy, double speed,
                               double height, double knot_interval, double ramp_s) {
  constexpr const char* kFn = "makeDrivePath";
  requirePositive(speed, "speed", kFn);
  requirePositive(knot_interval, "knot_interval", kFn);
  if (!(ramp_s >= 0) || !std::isfinite(ramp_s) || !std::isfinite(height)) {
    throw std::invalid_argument("makeDrivePath: ramp_s must be >= 0 and height finite");
  }
  const Polyline path(waypoints_xy);
  if (path.length() < speed * ramp_s) {
    throw std::invalid_argument("makeDrivePath: the path (" + std::to_string(path.length()) +
                                " m) is shorter than the speed ramps need (speed * ramp_s = " +
                                std::to_string(speed * ramp_s) + " m)");
  }
  const SpeedProfile profile(path.length(), speed, ramp_s);
  // The profile starts one knot late and the curve ends two knots after it, so the first three
  // and the last three controls coincide with the end waypoints: the curve is then exactly at
  // rest there (equal controls c[k..k+2] give zero velocity and acceleration at the knot).
  const auto distanceAt = [&](double t) { return profile.distanceAt(t - knot_interval); };
  const std::size_t n = controlCountFor(profile.duration(), knot_interval) + 2;
  std::vector<Eigen::Vector3d> positions(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (static_cast<double>(i) - 1.0) * knot_interval;
    const Eigen::Vector2d xy = path.pointAt(distanceAt(t));
    positions[i] = Eigen::Vector3d(xy.x(), xy.y(), height);
  }

  // Yaw: the heading of the rounded curve itself (not of the polyline), sampled at the knots and
  // interpolated there, so the body x axis stays tangent through the turns; at rest the heading
  // is undefined and the polyline's is used.
  const SplineTrajectory position_only(
      positions, std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero()), knot_interval, 0.0);
  std::vector<double> yaws(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (static_cast<double>(i) - 1.0) * knot_interval;
    const double t_on_curve = std::clamp(t, position_only.startTime(), position_only.endTime());
    const Eigen::Vector3d v = position_only.sample(t_on_curve).velocity_world;
    yaws[i] = v.head<2>().norm() > 1e-3 * speed ? std::atan2(v.y(), v.x())
                                                : path.headingAt(distanceAt(t));
  }
  unwrapAngles(yaws);
  interpolateThroughKnots(yaws);
  std::vector<Eigen::Vector3d> ypr(n, Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < n; ++i) ypr[i][0] = yaws[i];
  return SplineTrajectory(std::move(positions), std::move(ypr), knot_interval, 0.0);
}

}  // namespace dynslam::sim
