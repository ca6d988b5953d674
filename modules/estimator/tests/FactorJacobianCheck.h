#pragma once
// Checks a factor's analytic Jacobians against central differences taken along each block's
// own Plus (PoseManifold for pose blocks, + for the others), in the tangent space where the
// factors write them (StateBlocks.h). Used by every factor's test.
#include <dynslam/estimator/StateBlocks.h>

#include <ceres/cost_function.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace dynslam::estimator::testing {

struct JacobianMismatch {
  double max_abs_error = 0;  ///< largest |analytic - numeric| over all blocks
  double max_rel_error = 0;  ///< the same relative to max(1, |numeric|)
  std::string where;         ///< "block b, row r, col c" of the largest relative error
};

/// `blocks[i]` holds the values of parameter block i; `isPose[i]` says whether it lives on
/// PoseManifold (7 values, 6 tangent columns) or is Euclidean.
inline JacobianMismatch compareJacobians(const ceres::CostFunction& f,
                                         std::vector<std::vector<double>> blocks,
                                         const std::vector<bool>& isPose, double step = 1e-6) {
  const int nr = f.num_residuals();
  const auto& sizes = f.parameter_block_sizes();
  std::vector<double*> params;
  for (auto& b : blocks) params.push_back(b.data());
  std::vector<std::vector<double>> jac(blocks.size());
  std::vector<double*> jacPtr;
  for (size_t i = 0; i < blocks.size(); ++i) {
    jac[i].assign(size_t(nr) * sizes[i], 0.0);
    jacPtr.push_back(jac[i].data());
  }
  Eigen::VectorXd r0(nr);
  f.Evaluate(params.data(), r0.data(), jacPtr.data());

  JacobianMismatch out;
  PoseManifold manifold;
  for (size_t i = 0; i < blocks.size(); ++i) {
    const int tangent = isPose[i] ? kPoseTangentSize : sizes[i];
    for (int c = 0; c < tangent; ++c) {
      Eigen::VectorXd rPlus(nr), rMinus(nr);
      for (int sign : {+1, -1}) {
        std::vector<std::vector<double>> moved = blocks;
        if (isPose[i]) {
          double delta[6] = {0, 0, 0, 0, 0, 0};
          delta[c] = sign * step;
          manifold.Plus(blocks[i].data(), delta, moved[i].data());
        } else {
          moved[i][c] += sign * step;
        }
        std::vector<double*> p;
        for (auto& b : moved) p.push_back(b.data());
        f.Evaluate(p.data(), (sign > 0 ? rPlus : rMinus).data(), nullptr);
      }
      const Eigen::VectorXd numeric = (rPlus - rMinus) / (2 * step);
      for (int r = 0; r < nr; ++r) {
        const double analytic = jac[i][size_t(r) * sizes[i] + c];
        const double abs = std::abs(analytic - numeric(r));
        const double rel = abs / std::max(1.0, std::abs(numeric(r)));
        out.max_abs_error = std::max(out.max_abs_error, abs);
        if (rel > out.max_rel_error) {
          out.max_rel_error = rel;
          out.where = "block " + std::to_string(i) + ", row " + std::to_string(r) + ", col " +
                      std::to_string(c) + ": analytic " + std::to_string(analytic) +
                      ", numeric " + std::to_string(numeric(r));
        }
      }
    }
    if (isPose[i])  // the 7th column must be zero (see StateBlocks.h)
      for (int r = 0; r < nr; ++r)
        if (jac[i][size_t(r) * sizes[i] + 6] != 0.0) {
          out.max_rel_error = std::max(out.max_rel_error, 1.0);
          out.where = "block " + std::to_string(i) + ": 7th column not zero";
        }
  }
  return out;
}

}  // namespace dynslam::estimator::testing
