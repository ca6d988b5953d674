#include "dynslam/estimator/factors/MarginalizationFactor.h"

#include "dynslam/estimator/StateBlocks.h"

#include <cmath>
#include <stdexcept>

namespace dynslam::estimator {

MarginalizationFactor::MarginalizationFactor(std::vector<PriorBlock> blocks, Eigen::MatrixXd J,
                                             Eigen::VectorXd r0)
    : blocks_(std::move(blocks)), J_(std::move(J)), r0_(std::move(r0)) {
  int columns = 0;
  for (const auto& b : blocks_) {
    if (int(b.x0.size()) != b.size || (b.is_pose && b.size != kPoseSize))
      throw std::invalid_argument("MarginalizationFactor: block size and value do not agree");
    offsets_.push_back(columns);
    columns += b.is_pose ? kPoseTangentSize : b.size;
    mutable_parameter_block_sizes()->push_back(b.size);
  }
  if (J_.cols() != columns || J_.rows() != r0_.size() || J_.rows() == 0)
    throw std::invalid_argument("MarginalizationFactor: J is " + std::to_string(J_.rows()) + "x" +
                                std::to_string(J_.cols()) + ", expected " +
                                std::to_string(r0_.size()) + "x" + std::to_string(columns));
  set_num_residuals(int(J_.rows()));
}

bool MarginalizationFactor::Evaluate(double const* const* parameters, double* residuals,
                                     double** jacobians) const {
  Eigen::VectorXd dx(J_.cols());
  std::vector<Eigen::Matrix3d> rotationJacobian(blocks_.size(), Eigen::Matrix3d::Identity());
  const PoseManifold manifold;
  for (size_t i = 0; i < blocks_.size(); ++i) {
    const auto& b = blocks_[i];
    if (b.is_pose) {
      double d[kPoseTangentSize];
      manifold.Minus(parameters[i], b.x0.data(), d);
      dx.segment<kPoseTangentSize>(offsets_[i]) = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(d);
      rotationJacobian[i] = inverseRightJacobianSO3(Eigen::Vector3d(d[3], d[4], d[5]));
    } else {
      for (int k = 0; k < b.size; ++k) dx(offsets_[i] + k) = parameters[i][k] - b.x0[k];
    }
  }
  Eigen::Map<Eigen::VectorXd>(residuals, J_.rows()) = r0_ + J_ * dx;
  if (!jacobians) return true;
  for (size_t i = 0; i < blocks_.size(); ++i) {
    if (!jacobians[i]) continue;
    const auto& b = blocks_[i];
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Ji(
        jacobians[i], J_.rows(), b.size);
    Ji.setZero();
    if (b.is_pose) {
      Ji.leftCols<3>() = J_.middleCols<3>(offsets_[i]);
      Ji.middleCols<3>(3) = J_.middleCols<3>(offsets_[i] + 3) * rotationJacobian[i];
    } else {
      Ji = J_.middleCols(offsets_[i], b.size);
    }
  }
  return true;
}

}  // namespace dynslam::estimator
