#pragma once
// Gyroscope and accelerometer samples from a SplineTrajectory: the exact specific force and
// angular rate in the IMU frame, plus white noise and a bias random walk (continuous-time
// densities, discretised at the sample rate as Kalibr/VINS define them).
#include <dynslam/sim/SplineTrajectory.h>

#include <cstdint>
#include <random>
#include <vector>

namespace dynslam::sim {

/// Defaults: the BMI055 of an Intel RealSense D455, as commonly calibrated with Kalibr.
struct ImuNoiseOptions {
  double rate_hz = 200.0;
  double gyro_noise_density = 1.7e-4;                    ///< rad/s/sqrt(Hz)
  double gyro_bias_random_walk = 2.0e-5;                 ///< rad/s^2/sqrt(Hz)
  double acc_noise_density = 2.0e-3;                     ///< m/s^2/sqrt(Hz)
  double acc_bias_random_walk = 3.0e-4;                  ///< m/s^3/sqrt(Hz)
  Eigen::Vector3d gyro_bias0 = Eigen::Vector3d::Zero();  ///< initial bias, rad/s
  Eigen::Vector3d acc_bias0 = Eigen::Vector3d::Zero();   ///< initial bias, m/s^2
  double gravity = 9.81;                                 ///< m/s^2
  bool noise = true;  ///< false: exact measurements (biases stay at their initial values)
};

struct ImuMeasurement {
  double t = 0;
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();       ///< what the sensor reports, IMU frame
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();        ///< what the sensor reports, IMU frame
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();  ///< the true bias at t (ground truth)
  Eigen::Vector3d acc_bias = Eigen::Vector3d::Zero();   ///< the true bias at t (ground truth)
};

/// The exact motion of the IMU frame at one instant (no noise, no bias).
struct ImuKinematics {
  Eigen::Isometry3d T_world_imu = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity_world = Eigen::Vector3d::Zero();    ///< of the IMU origin, m/s
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  ///< IMU frame, rad/s
  Eigen::Vector3d specific_force = Eigen::Vector3d::Zero();    ///< IMU frame, m/s^2
};

/// With R = R_body_imu, r = T_body_imu.translation() (the lever arm, body frame) and the body's
/// omega, alpha (body frame), a (world):
///   angular_velocity = R^T omega
///   a_imu_world      = a + R_world_body (alpha x r + omega x (omega x r))
///   specific_force   = R_world_imu^T (a_imu_world - g_world),  g_world = (0, 0, -gravity)
/// alpha comes analytically from the spline (TrajectorySample::angular_acceleration_body).
ImuKinematics imuKinematicsAt(const TrajectorySample& body, const Eigen::Isometry3d& T_body_imu,
                              double gravity);

/// The sensor: what it reports for the exact motion at each sample, with white noise and biases
/// that walk (the model and the draw order of synthesizeImu below). For motion known one sample
/// at a time (a robot driven in closed loop). Throws std::invalid_argument for a bad rate or a
/// negative noise parameter.
class ImuNoiseProcess {
 public:
  /// `rng` must outlive the process; it is drawn from at each measure() with noise on.
  ImuNoiseProcess(const ImuNoiseOptions& options, std::mt19937_64& rng);
  /// The report at t of the exact motion; the biases step after it.
  ImuMeasurement measure(double t, const ImuKinematics& exact);

 private:
  ImuNoiseOptions options_;
  std::mt19937_64& rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  double gyro_white_ = 0, acc_white_ = 0, gyro_walk_ = 0, acc_walk_ = 0;
  Eigen::Vector3d gyro_bias_ = Eigen::Vector3d::Zero(), acc_bias_ = Eigen::Vector3d::Zero();
};

/// Samples at uniformSampleTimes(t0, t1, options.rate_hz) (t0, t0 + 1/rate, ... <= t1).
/// T_body_imu is the IMU's pose in the body frame (the body of the trajectory); the
/// measurements are in the IMU frame. Sample k reports
///   gyro = angular_velocity + gyro_bias_k + n_g,   acc = specific_force + acc_bias_k + n_a
/// with n ~ N(0, density * sqrt(rate)) per axis, and after it the biases step by
/// N(0, random_walk * sqrt(1 / rate)) per axis (bias_0 = the options' initial biases).
/// The rng is consumed in a fixed order (per sample: gyro noise xyz, acc noise xyz, gyro bias
/// step xyz, acc bias step xyz), so a seed reproduces the sequence; noise = false draws nothing.
/// Throws std::invalid_argument for a bad rate or range or a negative noise parameter, and
/// std::out_of_range when [t0, t1] is not inside the trajectory's time range.
std::vector<ImuMeasurement> synthesizeImu(const SplineTrajectory& trajectory, double t0, double t1,
                                          const ImuNoiseOptions& options,
                                          const Eigen::Isometry3d& T_body_imu,
                                          std::mt19937_64& rng);

}  // namespace dynslam::sim
