#include "dynslam/evaluation/Umeyama.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <limits>

namespace dynslam::evaluation {

SimilarityTransform umeyamaAlignment(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& y,
                                     bool with_scale) {
  if (x.cols() != y.cols()) throw EvaluationError("Umeyama: point sets differ in size");
  const Eigen::Index n = x.cols();
  if (n == 0) throw EvaluationError("Umeyama: no points to align");
  const double inv_n = 1.0 / static_cast<double>(n);

  // Means and variance of x (Umeyama eq. 34-36).
  const Eigen::Vector3d mean_x = x.rowwise().mean();
  const Eigen::Vector3d mean_y = y.rowwise().mean();
  const Eigen::Matrix3Xd x_centred = x.colwise() - mean_x;
  const Eigen::Matrix3Xd y_centred = y.colwise() - mean_y;
  const double sigma_x = inv_n * x_centred.squaredNorm();

  // Cross-covariance (eq. 38) and its SVD.
  const Eigen::Matrix3d cov_xy = inv_n * (y_centred * x_centred.transpose());
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov_xy, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d d = svd.singularValues();
  int rank = 0;
  for (int k = 0; k < 3; ++k)
    if (d(k) > std::numeric_limits<double>::epsilon()) ++rank;
  if (rank < 2) {
    throw EvaluationError(
        "degenerate covariance rank, Umeyama alignment is not possible (are all points on a "
        "line?)");
  }

  // S (eq. 43): flip the smallest axis when U V^T would be a reflection.
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) s(2, 2) = -1.0;

  SimilarityTransform result;
  result.rotation = svd.matrixU() * s * svd.matrixV().transpose();           // eq. 40
  result.scale = with_scale ? (d.asDiagonal() * s).trace() / sigma_x : 1.0;  // eq. 42
  result.translation = mean_y - result.scale * (result.rotation * mean_x);   // eq. 41
  return result;
}

}  // namespace dynslam::evaluation
