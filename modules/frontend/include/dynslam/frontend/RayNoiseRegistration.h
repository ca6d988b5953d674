#pragma once
// Rigid registration weighted by how a depth camera measures a point: finely across its ray (the
// pixel: sigma_px z / f, about 2 mm at 9 m) and coarsely along it (the depth reading: 3-12 cm at
// 9 m on a D455-like sensor). Kabsch's plain least squares (method.md section 4's precise
// registration) treats both alike, so an object moving along the line of sight, a car driving
// towards the camera, gets its motion from the depth differences alone. Here each pair's residual
// q - (R p + t) is weighed by the inverse of its covariance Sigma_q + R Sigma_p R^T (each point's
// covariance elongated along its ray): the linearised maximum likelihood of the pair with the
// point's true position marginalised. The rotation then comes mostly from the pixels, as in PnP
// (RayNoiseRegistrationTest: a car's corners 9 m away). More is gained on real tracks by the
// gate it allows (inliersOnRays). Not the method: the rigid point sets use it with
// [DynamicClassification] rigid_pixel_sigma > 0. Measured: docs/notes/frontend.md, 2026-11-28
// (front-end settings' history).
#include <dynslam/frontend/RigidRegistration.h>

#include <Eigen/Core>

#include <vector>

namespace dynslam::frontend {

/// Covariance of a point seen by a camera at the origin: sigma `along` its ray, `across` in the
/// two directions perpendicular to it.
Eigen::Matrix3d rayCovariance(const Eigen::Vector3d& point, double along, double across);

struct RayNoiseRefinement {
  int max_iterations = 5;  ///< Gauss-Newton steps from the start (a step under 1e-7 stops it)
  /// Residuals beyond this many sigmas (Mahalanobis) are down-weighted (Huber): a pair the
  /// isotropic RANSAC gate admitted can be sigmas off across the rays, where sigma is small.
  double huber_sigmas = 3.0;
};

/// Gauss-Newton from `initial` on min sum rho(r_i^T (Sigma_q,i + R Sigma_p,i R^T)^-1 r_i),
/// r_i = q_i - R p_i - t, over the pairs `indices` (all when empty); the covariances are one per
/// pair (all pairs). Rotation perturbed on the left. Stops when a step moves less than 1e-7;
/// returns `initial` when the normal equations are singular (fewer than 3 pairs, collinear).
RigidMotion refineOnRays(const std::vector<Eigen::Vector3d>& p,
                         const std::vector<Eigen::Vector3d>& q,
                         const std::vector<Eigen::Matrix3d>& covP,
                         const std::vector<Eigen::Matrix3d>& covQ, const RigidMotion& initial,
                         const std::vector<int>& indices = {}, const RayNoiseRefinement& opts = {});

/// The indices i among `indices` (all pairs when empty; kept in their order) whose residual lies
/// within `gateSigmas` of its own noise: r_i^T (Sigma_q,i + R Sigma_p,i R^T)^-1 r_i <
/// gateSigmas^2. Across the rays sigma is the pixel's, so a track that slid a few pixels off a
/// body (a swinging arm beside a torso, a corner on a silhouette) fails where an isotropic gate
/// of the depth noise (centimetres) admits it.
std::vector<int> inliersOnRays(const std::vector<Eigen::Vector3d>& p,
                               const std::vector<Eigen::Vector3d>& q,
                               const std::vector<Eigen::Matrix3d>& covP,
                               const std::vector<Eigen::Matrix3d>& covQ, const RigidMotion& motion,
                               double gateSigmas, const std::vector<int>& indices = {});

/// The translation minimising the same cost for a given rotation R (one linear solve): the
/// centroids weighted by each pair's information matrix. Needs >= 1 pair.
Eigen::Vector3d translationOnRays(const std::vector<Eigen::Vector3d>& p,
                                  const std::vector<Eigen::Vector3d>& q,
                                  const std::vector<Eigen::Matrix3d>& covP,
                                  const std::vector<Eigen::Matrix3d>& covQ,
                                  const Eigen::Matrix3d& R, const std::vector<int>& indices);

}  // namespace dynslam::frontend
