#pragma once
// r_b of method.md section 5: the IMU preintegration residual between keyframes i and j (as
// VINS-Mono's IMUFactor), 15 rows [dp, dtheta, dv, dba, dbg] whitened by the square root of
// the preintegrated covariance's inverse.
// Parameter blocks (StateBlocks.h): pose_i (7), speed-bias_i (9), pose_j (7), speed-bias_j (9),
// and the world gravity vector g (3): a state of the window, held unless the camera-IMU rotation
// is estimated (the gravity the IMU initialization found carries that rotation's error).
//   r_p  = R_i^T (p_j - p_i - v_i T - 1/2 g T^2) - alpha(ba_i, bg_i)
//   r_th = 2 vec(gamma(bg_i)^-1 R_i^T R_j)
//   r_v  = R_i^T (v_j - v_i - g T) - beta(ba_i, bg_i)
//   r_ba = ba_j - ba_i,  r_bg = bg_j - bg_i
// The bias corrections of alpha, beta, gamma are first-order (ImuPreintegration); the window
// repropagates the preintegration between solves when the bias moves far (it is not done here:
// Evaluate is const and runs on several threads).
#include <dynslam/estimator/imu/ImuPreintegration.h>

#include <ceres/sized_cost_function.h>

#include <memory>

namespace dynslam::estimator {

class ImuFactor : public ceres::SizedCostFunction<15, 7, 9, 7, 9, 3> {
 public:
  explicit ImuFactor(std::shared_ptr<const ImuPreintegration> preintegration);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  const ImuPreintegration& preintegration() const { return *preintegration_; }

 private:
  /// What the residual and its Jacobians share at one evaluation.
  struct Linearisation {
    Eigen::Quaterniond q_i, q_j, gamma;  ///< the poses' rotations; gamma at bg_i
    Eigen::Vector3d bg_i;
    Eigen::Matrix3d Ri_T;
    /// p_j - p_i - v_i T - g T^2 / 2 and v_j - v_i - g T (world)
    Eigen::Vector3d dp_world, dv_world;
    double T;                            ///< the preintegrated interval
  };
  // The Jacobians (row-major, whitened) by the five blocks.
  void poseJacobianI(const Linearisation& at, double* jacobian) const;
  void speedBiasJacobianI(const Linearisation& at, double* jacobian) const;
  void poseJacobianJ(const Linearisation& at, double* jacobian) const;
  void speedBiasJacobianJ(const Linearisation& at, double* jacobian) const;
  void gravityJacobian(const Linearisation& at, double* jacobian) const;

  std::shared_ptr<const ImuPreintegration> preintegration_;
  Eigen::Matrix<double, 15, 15> sqrt_information_;
};

}  // namespace dynslam::estimator
