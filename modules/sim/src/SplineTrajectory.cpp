#include <dynslam/sim/SplineTrajectory.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace dynslam::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Uniform cubic B-spline basis at u in [0, 1] and its first and second derivatives in u.
struct Basis {
  std::array<double, 4> value, d1, d2;
};

Basis basisAt(double u) {
  const double u2 = u * u, u3 = u2 * u, v = 1.0 - u;
  Basis b;
  b.value = {v * v * v / 6.0, (3 * u3 - 6 * u2 + 4) / 6.0, (-3 * u3 + 3 * u2 + 3 * u + 1) / 6.0,
             u3 / 6.0};
  b.d1 = {-v * v / 2.0, (3 * u2 - 4 * u) / 2.0, (-3 * u2 + 2 * u + 1) / 2.0, u2 / 2.0};
  b.d2 = {v, 3 * u - 2, 1 - 3 * u, u};
  return b;
}

/// Value and time derivatives of one spline channel over control points c[k..k+3].
struct Channel {
  Eigen::Vector3d value = Eigen::Vector3d::Zero(), d1 = Eigen::Vector3d::Zero(),
                  d2 = Eigen::Vector3d::Zero();
};

Channel evaluate(const std::vector<Eigen::Vector3d>& c, std::size_t k, const Basis& b, double dt) {
  Channel out;
  for (std::size_t j = 0; j < 4; ++j) {
    out.value += b.value[j] * c[k + j];
    out.d1 += b.d1[j] * c[k + j];
    out.d2 += b.d2[j] * c[k + j];
  }
  out.d1 /= dt;  // d/dt = (1 / dt) d/du
  out.d2 /= dt * dt;
  return out;
}

/// d/dt of eulerRatesToBodyRates(ypr), given the Euler rates.
Eigen::Matrix3d eulerRateMatrixDerivative(const Eigen::Vector3d& ypr,
                                          const Eigen::Vector3d& ypr_dot) {
  const double sp = std::sin(ypr[1]), cp = std::cos(ypr[1]);
  const double sr = std::sin(ypr[2]), cr = std::cos(ypr[2]);
  const double pitch_dot = ypr_dot[1], roll_dot = ypr_dot[2];
  Eigen::Matrix3d e_dot;
  e_dot << -cp * pitch_dot, 0, 0,                                    //
      cr * cp * roll_dot - sr * sp * pitch_dot, -sr * roll_dot, 0,   //
      -sr * cp * roll_dot - cr * sp * pitch_dot, -cr * roll_dot, 0;  //
  return e_dot;
}

void checkControls(const std::vector<Eigen::Vector3d>& positions,
                   const std::vector<Eigen::Vector3d>& ypr, double knot_interval) {
  if (positions.size() != ypr.size()) {
    std::ostringstream msg;
    msg << "SplineTrajectory: " << positions.size() << " control positions but " << ypr.size()
        << " control yaw/pitch/roll; they must match";
    throw std::invalid_argument(msg.str());
  }
  if (positions.size() < 4) {
    throw std::invalid_argument(
        "SplineTrajectory: a cubic B-spline needs at least 4 control "
        "points, got " +
        std::to_string(positions.size()));
  }
  if (!(knot_interval > 0) || !std::isfinite(knot_interval)) {
    throw std::invalid_argument(
        "SplineTrajectory: knot_interval must be a positive finite "
        "number of seconds, got " +
        std::to_string(knot_interval));
  }
  static const char* kAngleNames[3] = {"yaw", "pitch", "roll"};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite() || !ypr[i].allFinite()) {
      throw std::invalid_argument("SplineTrajectory: control point " + std::to_string(i) +
                                  " is not finite");
    }
    if (i == 0) continue;
    for (int a = 0; a < 3; ++a) {
      const double jump = ypr[i][a] - ypr[i - 1][a];
      if (std::abs(jump) > kPi) {
        std::ostringstream msg;
        msg << "SplineTrajectory: control " << kAngleNames[a] << " jumps by " << jump
            << " rad between points " << i - 1 << " and " << i
            << " (more than pi): unwrap the angles or shorten the knot interval";
        throw std::invalid_argument(msg.str());
      }
    }
  }
}

}  // namespace

Eigen::Matrix3d rotationFromYawPitchRoll(const Eigen::Vector3d& ypr) {
  return (Eigen::AngleAxisd(ypr[0], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(ypr[1], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(ypr[2], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d eulerRatesToBodyRates(const Eigen::Vector3d& ypr) {
  // omega_body = Rx^T Ry^T (yaw_dot z) + Rx^T (pitch_dot y) + roll_dot x.
  const double sp = std::sin(ypr[1]), cp = std::cos(ypr[1]);
  const double sr = std::sin(ypr[2]), cr = std::cos(ypr[2]);
  Eigen::Matrix3d e;
  e << -sp, 0, 1,      //
      sr * cp, cr, 0,  //
      cr * cp, -sr, 0;
  return e;
}

std::vector<double> uniformSampleTimes(double t0, double t1, double rate_hz) {
  if (!(rate_hz > 0) || !std::isfinite(rate_hz)) {
    throw std::invalid_argument(
        "uniformSampleTimes: rate must be a positive finite number of "
        "Hz, got " +
        std::to_string(rate_hz));
  }
  if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0) {
    std::ostringstream msg;
    msg << "uniformSampleTimes: need finite t0 <= t1, got [" << t0 << ", " << t1 << "]";
    throw std::invalid_argument(msg.str());
  }
  // Count from the interval rather than accumulating t += 1/rate, so the grid does not drift, and
  // let an exact multiple of the period keep its last sample despite rounding: of the product
  // (1e-9 samples) and of t1 - t0 itself (a few ulps of |t|, 2.4e-7 s for Unix-epoch stamps).
  const double slack = 1e-9 + 8 * std::numeric_limits<double>::epsilon() *
                                  std::max(std::abs(t0), std::abs(t1)) * rate_hz;
  const auto count = static_cast<std::size_t>(std::floor((t1 - t0) * rate_hz + slack)) + 1;
  std::vector<double> times(count);
  for (std::size_t k = 0; k < count; ++k) times[k] = t0 + static_cast<double>(k) / rate_hz;
  return times;
}

SplineTrajectory::SplineTrajectory(std::vector<Eigen::Vector3d> positions,
                                   std::vector<Eigen::Vector3d> yaw_pitch_roll,
                                   double knot_interval, double t0)
    : positions_(std::move(positions)),
      ypr_(std::move(yaw_pitch_roll)),
      dt_(knot_interval),
      t0_(t0) {
  checkControls(positions_, ypr_, dt_);
  if (!std::isfinite(t0_)) throw std::invalid_argument("SplineTrajectory: t0 is not finite");
}

double SplineTrajectory::startTime() const { return t0_; }

double SplineTrajectory::endTime() const {
  return t0_ + static_cast<double>(positions_.size() - 3) * dt_;
}

TrajectorySample SplineTrajectory::sample(double t) const {
  const double start = startTime(), end = endTime();
  const double tolerance = 1e-9 * dt_ + 1e-14 * std::max(std::abs(start), std::abs(end));
  if (!(t >= start - tolerance && t <= end + tolerance)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "SplineTrajectory::sample: t = " << t << " is outside the trajectory's time range ["
        << start << ", " << end << "]";
    throw std::out_of_range(msg.str());
  }
  const double s = (std::clamp(t, start, end) - t0_) / dt_;
  const std::size_t last_segment = positions_.size() - 4;
  const auto k = std::min(static_cast<std::size_t>(std::floor(s)), last_segment);
  const Basis basis = basisAt(s - static_cast<double>(k));

  const Channel position = evaluate(positions_, k, basis, dt_);
  const Channel angles = evaluate(ypr_, k, basis, dt_);

  TrajectorySample out;
  out.t = t;
  out.T_world_body.linear() = rotationFromYawPitchRoll(angles.value);
  out.T_world_body.translation() = position.value;
  out.velocity_world = position.d1;
  out.acceleration_world = position.d2;
  const Eigen::Matrix3d e = eulerRatesToBodyRates(angles.value);
  out.angular_velocity_body = e * angles.d1;
  out.angular_acceleration_body =
      e * angles.d2 + eulerRateMatrixDerivative(angles.value, angles.d1) * angles.d1;
  out.yaw_pitch_roll = angles.value;
  return out;
}

}  // namespace dynslam::sim
