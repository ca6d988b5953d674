#include <dynslam/sim/ImuSynthesizer.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

void requireNonNegative(double value, const char* what) {
  if (!(value >= 0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("synthesizeImu: ") + what +
                                " must be >= 0 and finite, got " + std::to_string(value));
  }
}

Eigen::Vector3d standardNormal3(std::normal_distribution<double>& normal, std::mt19937_64& rng) {
  // Explicit statements fix the draw order (argument evaluation order is unspecified).
  const double x = normal(rng);
  const double y = normal(rng);
  const double z = normal(rng);
  return {x, y, z};
}

}  // namespace

ImuKinematics imuKinematicsAt(const TrajectorySample& body, const Eigen::Isometry3d& T_body_imu,
                              double gravity) {
  const Eigen::Matrix3d& R_world_body = body.T_world_body.linear();
  const Eigen::Vector3d& omega = body.angular_velocity_body;
  const Eigen::Vector3d& alpha = body.angular_acceleration_body;
  const Eigen::Vector3d lever_arm = T_body_imu.translation();

  ImuKinematics out;
  out.T_world_imu = body.T_world_body * T_body_imu;
  out.velocity_world = body.velocity_world + R_world_body * omega.cross(lever_arm);
  const Eigen::Vector3d acceleration_world =
      body.acceleration_world +
      R_world_body * (alpha.cross(lever_arm) + omega.cross(omega.cross(lever_arm)));
  const Eigen::Vector3d gravity_world(0, 0, -gravity);
  out.angular_velocity = T_body_imu.linear().transpose() * omega;
  out.specific_force = out.T_world_imu.linear().transpose() * (acceleration_world - gravity_world);
  return out;
}

ImuNoiseProcess::ImuNoiseProcess(const ImuNoiseOptions& options, std::mt19937_64& rng)
    : options_(options), rng_(rng) {
  requireNonNegative(options.gyro_noise_density, "gyro_noise_density");
  requireNonNegative(options.gyro_bias_random_walk, "gyro_bias_random_walk");
  requireNonNegative(options.acc_noise_density, "acc_noise_density");
  requireNonNegative(options.acc_bias_random_walk, "acc_bias_random_walk");
  if (!options.gyro_bias0.allFinite() || !options.acc_bias0.allFinite() ||
      !std::isfinite(options.gravity)) {
    throw std::invalid_argument("synthesizeImu: initial biases and gravity must be finite");
  }
  if (!(options.rate_hz > 0) || !std::isfinite(options.rate_hz))
    throw std::invalid_argument("synthesizeImu: rate_hz must be > 0, got " +
                                std::to_string(options.rate_hz));
  // Discretisation of the continuous-time densities at the sample period (Kalibr's convention):
  // white noise sigma_d = density / sqrt(period), bias step sigma_d = random_walk * sqrt(period).
  const double period = 1.0 / options.rate_hz;
  gyro_white_ = options.gyro_noise_density / std::sqrt(period);
  acc_white_ = options.acc_noise_density / std::sqrt(period);
  gyro_walk_ = options.gyro_bias_random_walk * std::sqrt(period);
  acc_walk_ = options.acc_bias_random_walk * std::sqrt(period);
  gyro_bias_ = options.gyro_bias0;
  acc_bias_ = options.acc_bias0;
}

ImuMeasurement ImuNoiseProcess::measure(double t, const ImuKinematics& exact) {
  ImuMeasurement m;
  m.t = t;
  m.gyro_bias = gyro_bias_;
  m.acc_bias = acc_bias_;
  m.gyro = exact.angular_velocity + gyro_bias_;
  m.acc = exact.specific_force + acc_bias_;
  if (options_.noise) {
    m.gyro += gyro_white_ * standardNormal3(normal_, rng_);
    m.acc += acc_white_ * standardNormal3(normal_, rng_);
    gyro_bias_ += gyro_walk_ * standardNormal3(normal_, rng_);
    acc_bias_ += acc_walk_ * standardNormal3(normal_, rng_);
  }
  return m;
}

std::vector<ImuMeasurement> synthesizeImu(const SplineTrajectory& trajectory, double t0, double t1,
                                          const ImuNoiseOptions& options,
                                          const Eigen::Isometry3d& T_body_imu,
                                          std::mt19937_64& rng) {
  ImuNoiseProcess sensor(options, rng);
  const std::vector<double> times = uniformSampleTimes(t0, t1, options.rate_hz);
  std::vector<ImuMeasurement> out;
  out.reserve(times.size());
  for (const double t : times)
    out.push_back(
        sensor.measure(t, imuKinematicsAt(trajectory.sample(t), T_body_imu, options.gravity)));
  return out;
}

}  // namespace dynslam::sim
