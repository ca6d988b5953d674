#pragma once
// r_om (method.md section 5, paper Eq. 21): a rigid object moves the same way over two
// consecutive keyframe intervals. With object poses L = T_world_object (pose blocks) and the
// object-frame motion H_{a,b} = L_a^-1 L_b,
//
//   E = H_{n-2,n-1}^-1 H_{n-1,n} = (R_E, t_E),    r = S [t_E; Log_SO3(R_E)]            (6)
//
// S is the square root of the information given at construction. The paper writes Log in se(3);
// we take rotation and translation apart (Log on SO(3) x R^3): the Jacobians stay short (right
// Jacobian of SO(3) only, no SE(3) Q-blocks), both forms vanish together and agree to first order
// near E = I, where this prior lives. The order [translation; rotation] follows the pose tangent.
// Motion "per keyframe interval", as Eq. 21: with very unequal intervals the caller scales the
// information. Blocks: L_{n-2} (7), L_{n-1} (7), L_n (7).
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

namespace dynslam::estimator {

class RigidSmoothMotionFactor : public ceres::SizedCostFunction<6, 7, 7, 7> {
 public:
  using Matrix6d = Eigen::Matrix<double, 6, 6>;

  /// `information` (6x6, symmetric positive definite) of [t_E (m); rotation (rad)].
  explicit RigidSmoothMotionFactor(const Matrix6d& information);
  /// Diagonal information from one sigma for translation and one for rotation.
  RigidSmoothMotionFactor(double sigma_translation, double sigma_rotation);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Matrix6d sqrt_information_;
};

}  // namespace dynslam::estimator
