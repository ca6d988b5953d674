#pragma once
// Rigid registration of matched 3-D point pairs (method.md section 4): the least-squares motion
// min sum |q_i - R p_i - t|^2 (Kabsch/Horn by SVD, Eigen::umeyama without scaling), and the
// coarse 4-point RANSAC around it. Pure Eigen: used for the rigid point sets of dynamic objects
// and for the camera's own motion from the background points (SceneFlow.h).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace dynslam::frontend {

/// q = R p + t.
struct RigidMotion {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return R * p + t; }
  Eigen::Isometry3d isometry() const;
  static RigidMotion from(const Eigen::Isometry3d& T);
};

/// Settings of the coarse registration (ini keys in DynamicClassificationOptions).
struct RansacParams {
  int iterations = 100;             ///< hypotheses drawn (method.md: 100)
  int sample_size = 4;              ///< pairs per hypothesis (method.md: 4)
  double inlier_threshold = 0.03;   ///< m; |R p + t - q| below this is an inlier (method: tau)
};

struct RegistrationResult {
  RigidMotion motion;                 ///< precise registration on all inliers
  std::vector<int> inliers;           ///< indices into the pairs, ascending
};

/// Least-squares motion of the pairs `indices` (all pairs when empty): centroids removed, R by
/// SVD with the reflection fixed, t = mean(q) - R mean(p). Needs >= 3 pairs (throws
/// std::invalid_argument otherwise); degenerate (collinear) sets give some minimiser.
/// `weights` (one per pair, all pairs; empty: equal) minimise sum w_i |q_i - R p_i - t|^2
/// instead: weighted centroids and cross-covariance (Eigen::umeyama has no weights).
RigidMotion kabsch(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
                   const std::vector<int>& indices = {}, const std::vector<double>& weights = {});

/// Indices i with |motion(p_i) - q_i| < threshold (gates[i] when `gates` is not empty: one
/// threshold per pair), ascending.
std::vector<int> inliersOf(const RigidMotion& motion, const std::vector<Eigen::Vector3d>& p,
                           const std::vector<Eigen::Vector3d>& q, double threshold,
                           const std::vector<double>& gates = {});

/// Coarse + precise registration (method.md section 4). Each of `iterations` hypotheses is the
/// Kabsch motion of `sample_size` distinct pairs drawn from `candidates` (all pairs when empty);
/// inliers are counted over ALL pairs, and the largest inlier set wins (first found on ties).
/// `extra` hypotheses (a motion predicted from the IMU, the previous frame's motion) compete
/// with the drawn ones. The precise registration is the Kabsch motion of the winner's inliers,
/// whose inliers are then recounted once; `weights` (per pair, empty: equal) weigh that precise
/// fit only; `gates` (per pair, m; empty: params.inlier_threshold for all) replace the inlier
/// threshold pair by pair. nullopt when fewer than sample_size pairs (or candidates) exist or
/// the best set has fewer than 3 inliers. Deterministic for a given `rng` state.
std::optional<RegistrationResult> registerRansac(const std::vector<Eigen::Vector3d>& p,
                                                 const std::vector<Eigen::Vector3d>& q,
                                                 const RansacParams& params, std::mt19937& rng,
                                                 const std::vector<int>& candidates = {},
                                                 const std::vector<RigidMotion>& extra = {},
                                                 const std::vector<double>& weights = {},
                                                 const std::vector<double>& gates = {});

/// Rotation angle of R, degrees.
double rotationAngleDeg(const Eigen::Matrix3d& R);

}  // namespace dynslam::frontend
