#include "dynslam/frontend/RayNoiseRegistration.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::frontend {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

/// The covariance of a pair's residual q - (R p + t), from its points' covariances.
Eigen::Matrix3d residualCovariance(const Eigen::Matrix3d& covP, const Eigen::Matrix3d& covQ,
                                   const Eigen::Matrix3d& R) {
  return covQ + R * covP * R.transpose();
}

}  // namespace

Eigen::Matrix3d rayCovariance(const Eigen::Vector3d& point, double along, double across) {
  const double n = point.norm();
  if (!(n > 0)) return Eigen::Matrix3d::Identity() * (along * along);
  const Eigen::Vector3d u = point / n;
  const Eigen::Matrix3d uu = u * u.transpose();
  return along * along * uu + across * across * (Eigen::Matrix3d::Identity() - uu);
}

RigidMotion refineOnRays(const std::vector<Eigen::Vector3d>& p,
                         const std::vector<Eigen::Vector3d>& q,
                         const std::vector<Eigen::Matrix3d>& covP,
                         const std::vector<Eigen::Matrix3d>& covQ, const RigidMotion& initial,
                         const std::vector<int>& indices, const RayNoiseRefinement& opts) {
  if (p.size() != q.size() || covP.size() != p.size() || covQ.size() != p.size())
    throw std::invalid_argument("refineOnRays: " + std::to_string(p.size()) + " points p, " +
                                std::to_string(q.size()) + " points q, " +
                                std::to_string(covP.size()) + " and " +
                                std::to_string(covQ.size()) + " covariances");
  const size_t n = indices.empty() ? p.size() : indices.size();
  if (n < 3) return initial;
  auto at = [&](size_t k) { return indices.empty() ? k : size_t(indices[k]); };
  RigidMotion m = initial;
  for (int it = 0; it < opts.max_iterations; ++it) {
    Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
    for (size_t k = 0; k < n; ++k) {
      const size_t i = at(k);
      const Eigen::Vector3d Rp = m.R * p[i];
      const Eigen::Vector3d r = q[i] - Rp - m.t;
      // The information of the pair at the current rotation (held fixed within the step).
      const Eigen::Matrix3d W = residualCovariance(covP[i], covQ[i], m.R).inverse();
      const double mahalanobis = std::sqrt(std::max(0.0, r.dot(W * r)));
      const double huber = mahalanobis > opts.huber_sigmas ? opts.huber_sigmas / mahalanobis : 1;
      // r(omega, dt) ~ r + [R p]x omega - dt for R <- Exp(omega) R, t <- t + dt.
      Eigen::Matrix<double, 3, 6> J;
      J.leftCols<3>() = skew(Rp);
      J.rightCols<3>() = -Eigen::Matrix3d::Identity();
      H += huber * J.transpose() * W * J;
      g += huber * J.transpose() * W * r;
    }
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(H);
    if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return m;
    const Eigen::Matrix<double, 6, 1> step = -ldlt.solve(g);
    if (!step.allFinite()) return m;
    const Eigen::Vector3d omega = step.head<3>();
    if (omega.norm() > 0)
      m.R = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix() * m.R;
    m.t += step.tail<3>();
    if (step.norm() < 1e-7) break;
  }
  return m;
}

std::vector<int> inliersOnRays(const std::vector<Eigen::Vector3d>& p,
                               const std::vector<Eigen::Vector3d>& q,
                               const std::vector<Eigen::Matrix3d>& covP,
                               const std::vector<Eigen::Matrix3d>& covQ, const RigidMotion& motion,
                               double gateSigmas, const std::vector<int>& indices) {
  const size_t pairs = std::min({p.size(), q.size(), covP.size(), covQ.size()});
  const size_t n = indices.empty() ? pairs : indices.size();
  std::vector<int> inliers;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = indices.empty() ? k : size_t(indices[k]);
    if (i >= pairs) continue;
    const Eigen::Vector3d r = q[i] - motion.apply(p[i]);
    const Eigen::Matrix3d C = residualCovariance(covP[i], covQ[i], motion.R);
    if (r.dot(C.ldlt().solve(r)) < gateSigmas * gateSigmas) inliers.push_back(int(i));
  }
  return inliers;
}

Eigen::Vector3d translationOnRays(const std::vector<Eigen::Vector3d>& p,
                                  const std::vector<Eigen::Vector3d>& q,
                                  const std::vector<Eigen::Matrix3d>& covP,
                                  const std::vector<Eigen::Matrix3d>& covQ,
                                  const Eigen::Matrix3d& R, const std::vector<int>& indices) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const int i : indices) {
    const auto k = size_t(i);
    const Eigen::Matrix3d W = residualCovariance(covP[k], covQ[k], R).inverse();
    A += W;
    b += W * (q[k] - R * p[k]);
  }
  return A.ldlt().solve(b);
}

}  // namespace dynslam::frontend
