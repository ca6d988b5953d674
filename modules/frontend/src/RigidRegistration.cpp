#include "dynslam/frontend/RigidRegistration.h"

#include <Eigen/Geometry>  // Eigen::umeyama
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dynslam::frontend {

Eigen::Isometry3d RigidMotion::isometry() const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = t;
  return T;
}

RigidMotion RigidMotion::from(const Eigen::Isometry3d& T) { return {T.linear(), T.translation()}; }

namespace {

RigidMotion weightedKabsch(const std::vector<Eigen::Vector3d>& p,
                           const std::vector<Eigen::Vector3d>& q, const std::vector<int>& indices,
                           const std::vector<double>& w) {
  const size_t n = indices.empty() ? p.size() : indices.size();
  auto at = [&](size_t k) { return indices.empty() ? k : size_t(indices[k]); };
  double W = 0;
  Eigen::Vector3d mp = Eigen::Vector3d::Zero(), mq = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < n; ++k) {
    const size_t i = at(k);
    W += w[i];
    mp += w[i] * p[i];
    mq += w[i] * q[i];
  }
  if (!(W > 0)) throw std::invalid_argument("kabsch: the weights of the pairs sum to zero");
  mp /= W;
  mq /= W;
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (size_t k = 0; k < n; ++k) {
    const size_t i = at(k);
    H += w[i] * (q[i] - mq) * (p[i] - mp).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) S(2, 2) = -1;
  const Eigen::Matrix3d R = svd.matrixU() * S * svd.matrixV().transpose();
  return {R, mq - R * mp};
}

}  // namespace

RigidMotion kabsch(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
                   const std::vector<int>& indices, const std::vector<double>& weights) {
  if (p.size() != q.size())
    throw std::invalid_argument("kabsch: " + std::to_string(p.size()) + " points p but " +
                                std::to_string(q.size()) + " points q");
  const Eigen::Index n = indices.empty() ? Eigen::Index(p.size()) : Eigen::Index(indices.size());
  if (n < 3)
    throw std::invalid_argument("kabsch: needs at least 3 point pairs, got " + std::to_string(n));
  if (!weights.empty()) {
    if (weights.size() != p.size())
      throw std::invalid_argument("kabsch: " + std::to_string(weights.size()) + " weights for " +
                                  std::to_string(p.size()) + " pairs");
    return weightedKabsch(p, q, indices, weights);
  }
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const size_t i = indices.empty() ? size_t(k) : size_t(indices[size_t(k)]);
    src.col(k) = p[i];
    dst.col(k) = q[i];
  }
  // Umeyama's closed form without scaling is the Kabsch/Horn solution: centroids removed, R
  // from the SVD of the cross-covariance with det(R) = +1, t = mean(q) - R mean(p).
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, false);
  return {T.topLeftCorner<3, 3>(), T.topRightCorner<3, 1>()};
}

std::vector<int> inliersOf(const RigidMotion& motion, const std::vector<Eigen::Vector3d>& p,
                           const std::vector<Eigen::Vector3d>& q, double threshold,
                           const std::vector<double>& gates) {
  std::vector<int> inliers;
  const double t2 = threshold * threshold;
  for (size_t i = 0; i < p.size(); ++i) {
    const double g2 = gates.empty() ? t2 : gates[i] * gates[i];
    if ((motion.apply(p[i]) - q[i]).squaredNorm() < g2) inliers.push_back(int(i));
  }
  return inliers;
}

std::optional<RegistrationResult> registerRansac(const std::vector<Eigen::Vector3d>& p,
                                                 const std::vector<Eigen::Vector3d>& q,
                                                 const RansacParams& params, std::mt19937& rng,
                                                 const std::vector<int>& candidates,
                                                 const std::vector<RigidMotion>& extra,
                                                 const std::vector<double>& weights,
                                                 const std::vector<double>& gates) {
  if (p.size() != q.size())
    throw std::invalid_argument("registerRansac: point counts differ (" +
                                std::to_string(p.size()) + " vs " + std::to_string(q.size()) +
                                ")");
  if (!gates.empty() && gates.size() != p.size())
    throw std::invalid_argument("registerRansac: " + std::to_string(gates.size()) +
                                " gates for " + std::to_string(p.size()) + " pairs");
  std::vector<int> pool = candidates;
  if (pool.empty()) {
    pool.resize(p.size());
    std::iota(pool.begin(), pool.end(), 0);
  }
  const int k = std::max(3, params.sample_size);
  std::vector<int> best;
  auto consider = [&](const RigidMotion& m) {
    std::vector<int> in = inliersOf(m, p, q, params.inlier_threshold, gates);
    if (in.size() > best.size()) best = std::move(in);
  };
  for (const auto& m : extra) consider(m);
  if (int(pool.size()) >= k) {
    std::vector<int> sample(static_cast<size_t>(k), 0);
    for (int it = 0; it < params.iterations; ++it) {
      // k distinct pool entries by a partial Fisher-Yates shuffle (deterministic given rng).
      for (int j = 0; j < k; ++j) {
        std::uniform_int_distribution<size_t> pick(size_t(j), pool.size() - 1);
        std::swap(pool[size_t(j)], pool[pick(rng)]);
        sample[size_t(j)] = pool[size_t(j)];
      }
      consider(kabsch(p, q, sample));
    }
  }
  if (best.size() < 3) return std::nullopt;
  RegistrationResult r;
  r.motion = kabsch(p, q, best, weights);
  r.inliers = inliersOf(r.motion, p, q, params.inlier_threshold, gates);
  if (r.inliers.size() < 3) {  // the refit lost points: keep the hypothesis' own set
    r.inliers = best;
  } else if (r.inliers != best) {
    r.motion = kabsch(p, q, r.inliers, weights);
  }
  return r;
}

double rotationAngleDeg(const Eigen::Matrix3d& R) {
  return Eigen::AngleAxisd(R).angle() * 180.0 / M_PI;
}

}  // namespace dynslam::frontend
