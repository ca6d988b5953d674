#pragma once
// r_p of method.md section 5: the prior the marginalised states leave on the states they were
// connected to (VINS-Fusion's MarginalizationFactor). At the linearisation point x0 the
// marginalised part of the cost was replaced by the quadratic |J dx + r0|^2, with dx = x [-] x0
// per kept block (PoseManifold::Minus for poses: [p - p0, Log(R0^T R)], x - x0 otherwise).
// Also serves as a plain Gaussian prior: J = square-root information, r0 = 0, x0 = the mean.
#include <ceres/cost_function.h>

#include <Eigen/Core>

#include <vector>

namespace dynslam::estimator {

/// One parameter block the prior constrains, with its value at the linearisation point.
struct PriorBlock {
  int size = 0;          ///< ambient size (7 for a pose, else the block's size)
  bool is_pose = false;  ///< on PoseManifold (6 tangent columns of J)
  std::vector<double> x0;
};

class MarginalizationFactor : public ceres::CostFunction {
 public:
  /// `J` has one row per residual and one column per tangent coordinate of the blocks, in
  /// order (6 per pose, size otherwise); `r0` one entry per row.
  MarginalizationFactor(std::vector<PriorBlock> blocks, Eigen::MatrixXd J, Eigen::VectorXd r0);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  const std::vector<PriorBlock>& blocks() const { return blocks_; }

 private:
  std::vector<PriorBlock> blocks_;
  std::vector<int> offsets_;  // first tangent column of each block in J_
  Eigen::MatrixXd J_;
  Eigen::VectorXd r0_;
};

}  // namespace dynslam::estimator
