#pragma once
// Least-squares similarity between two registered point sets (Umeyama, IEEE PAMI 1991), as in
// evo.core.geometry.umeyama_alignment.
#include <Eigen/Core>

namespace dynslam::evaluation {

/// y = scale * rotation * x + translation.
struct SimilarityTransform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const {
    return scale * (rotation * x) + translation;
  }
};

/// Finds the transform that maps the columns of `x` onto the columns of `y` (both 3 x n) with
/// the least sum of squared distances; scale stays 1 unless `with_scale`. A proper rotation is
/// returned even when the best orthogonal fit is a reflection (Kabsch sign correction).
/// Throws EvaluationError when the shapes differ, there are no points, or the cross-covariance
/// has rank < 2 (all points on a line or one point: the rotation is not defined).
SimilarityTransform umeyamaAlignment(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y,
                                     bool with_scale);

}  // namespace dynslam::evaluation
