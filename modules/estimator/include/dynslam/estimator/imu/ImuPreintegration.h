#pragma once
// IMU preintegration between two keyframes (method.md section 5, r_b; as VINS-Mono/Fusion):
// the relative position alpha, velocity beta and rotation gamma of the body (IMU) frame at
// keyframe j seen from keyframe i, integrated from the raw samples with the biases fixed at a
// linearisation point (midpoint rule), together with
//  - the first-order Jacobians of alpha, beta, gamma with respect to the biases, so that a small
//    change of the bias estimate corrects them without integrating again;
//  - their covariance, propagated from the sensor's noise densities.
// When the bias estimate moves far from the linearisation point the first-order correction is
// no longer good: needsRepropagation() says so and repropagate() integrates again.
//
// Conventions: world frame z up, gravity g_w = (0, 0, -g); the accelerometer measures
// a_m = R_wb^T (a_w - g_w) + b_a + noise, the gyroscope w_m = w + b_g + noise. Then
//   p_j = p_i + v_i T + 1/2 g_w T^2 + R_i alpha,  v_j = v_i + g_w T + R_i beta,  R_j = R_i gamma.
// Error-state order (15): [dp, dtheta, dv, dba, dbg] (VINS's O_P, O_R, O_V, O_BA, O_BG).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace dynslam::estimator {

/// Continuous-time noise densities of the IMU (the datasheet / Kalibr values).
struct ImuNoise {
  double acc_noise = 0.08;        ///< m/s^2/sqrt(Hz), accelerometer white noise
  double gyro_noise = 0.004;      ///< rad/s/sqrt(Hz), gyroscope white noise
  double acc_random_walk = 4e-4;  ///< m/s^3/sqrt(Hz), accelerometer bias random walk
  double gyro_random_walk = 2e-5; ///< rad/s^2/sqrt(Hz), gyroscope bias random walk
};

using Matrix15d = Eigen::Matrix<double, 15, 15>;

class ImuPreintegration {
 public:
  /// Starts at the sample (acc0, gyr0) taken at the first keyframe's time, with the bias
  /// linearisation point (ba, bg).
  ImuPreintegration(const Eigen::Vector3d& acc0, const Eigen::Vector3d& gyr0,
                    const Eigen::Vector3d& ba, const Eigen::Vector3d& bg, const ImuNoise& noise);

  /// Integrates one more sample taken dt seconds after the previous one (dt > 0).
  void push(double dt, const Eigen::Vector3d& acc, const Eigen::Vector3d& gyr);

  /// Integrates all pushed samples again with a new linearisation point.
  void repropagate(const Eigen::Vector3d& ba, const Eigen::Vector3d& bg);

  /// True when (ba, bg) is so far from the linearisation point that the first-order correction
  /// is poor (VINS's thresholds: 0.10 m/s^2, 0.01 rad/s).
  bool needsRepropagation(const Eigen::Vector3d& ba, const Eigen::Vector3d& bg) const;

  /// alpha, beta, gamma corrected to first order for biases (ba, bg).
  Eigen::Vector3d deltaPosition(const Eigen::Vector3d& ba, const Eigen::Vector3d& bg) const;
  Eigen::Vector3d deltaVelocity(const Eigen::Vector3d& ba, const Eigen::Vector3d& bg) const;
  Eigen::Quaterniond deltaRotation(const Eigen::Vector3d& bg) const;

  /// Predicts the state at the last sample from the state at the first (biases held).
  void predict(const Eigen::Vector3d& p_i, const Eigen::Quaterniond& q_i,
               const Eigen::Vector3d& v_i, const Eigen::Vector3d& ba, const Eigen::Vector3d& bg,
               const Eigen::Vector3d& gravity, Eigen::Vector3d& p_j, Eigen::Quaterniond& q_j,
               Eigen::Vector3d& v_j) const;

  double sumDt() const { return sum_dt_; }
  const Eigen::Vector3d& alpha() const { return alpha_; }
  const Eigen::Vector3d& beta() const { return beta_; }
  const Eigen::Quaterniond& gamma() const { return gamma_; }
  const Eigen::Vector3d& linearizedBa() const { return ba_; }
  const Eigen::Vector3d& linearizedBg() const { return bg_; }
  /// d[alpha, theta, beta, ba, bg] / d[.., ba, bg] (the last two blocks of columns are used).
  const Matrix15d& jacobian() const { return jacobian_; }
  const Matrix15d& covariance() const { return covariance_; }
  const ImuNoise& noise() const { return noise_; }

 private:
  struct Sample {
    double dt;
    Eigen::Vector3d acc, gyr;
  };
  void reset();
  void midpointStep(double dt, const Eigen::Vector3d& acc1, const Eigen::Vector3d& gyr1);

  ImuNoise noise_;
  Eigen::Vector3d acc0_, gyr0_;      // the first sample
  Eigen::Vector3d acc_, gyr_;        // the previous sample
  Eigen::Vector3d ba_, bg_;          // linearisation point
  std::vector<Sample> samples_;      // for repropagate()
  double sum_dt_ = 0;
  Eigen::Vector3d alpha_, beta_;
  Eigen::Quaterniond gamma_;
  Matrix15d jacobian_, covariance_;
};

}  // namespace dynslam::estimator
