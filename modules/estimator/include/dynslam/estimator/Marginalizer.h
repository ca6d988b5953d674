#pragma once
// Marginalisation by Schur complement (method.md section 5, as VINS-Fusion's
// MarginalizationInfo): the factors that touch the states leaving the window are linearised at
// the current values, the leaving states are eliminated from their normal equations, and what
// remains becomes one MarginalizationFactor on the states that stay.
//
// Robust losses are linearised the way Ceres does it (Triggs' correction), so a down-weighted
// outlier stays down-weighted in the prior.
#include <dynslam/estimator/factors/MarginalizationFactor.h>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>

#include <Eigen/Core>

#include <memory>
#include <set>
#include <vector>

namespace dynslam::estimator {

class Marginalizer {
 public:
  /// A factor touching some of the states; `loss` may be null (not owned: keep it alive until
  /// marginalize() returns). The block pointers must hold the current values.
  void addFactor(std::shared_ptr<const ceres::CostFunction> cost, const ceres::LossFunction* loss,
                 std::vector<double*> blocks);
  /// Declares a block as a pose on PoseManifold (6 tangent coordinates).
  void setPoseBlock(const double* block) { poses_.insert(block); }
  /// Declares a block held constant in the problem (e.g. a calibrated extrinsic): it is neither
  /// eliminated nor kept, its Jacobian columns are dropped.
  void setConstantBlock(const double* block) { constants_.insert(block); }

  struct Prior {
    std::shared_ptr<MarginalizationFactor> factor;  ///< null when nothing stays connected
    std::vector<double*> blocks;                    ///< the blocks it constrains, in order
  };

  /// Eliminates the blocks in `leaving` and returns the prior on every other block the factors
  /// touch. Eigenvalues below `eps` (relative to the largest) are treated as zero, as VINS does.
  Prior marginalize(const std::set<const double*>& leaving, double eps = 1e-8) const;

 private:
  struct Layout;
  /// Where each block's columns go in the normal equations.
  Layout layout(const std::set<const double*>& leaving) const;
  /// The normal equations of the factors, linearised at the blocks' current values.
  void accumulate(const Layout& layout, Eigen::MatrixXd& H, Eigen::VectorXd& g) const;

  struct Factor {
    std::shared_ptr<const ceres::CostFunction> cost;
    const ceres::LossFunction* loss;
    std::vector<double*> blocks;
  };
  std::vector<Factor> factors_;
  std::set<const double*> poses_, constants_;
};

}  // namespace dynslam::estimator
