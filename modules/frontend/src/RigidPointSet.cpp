#include "dynslam/frontend/RigidPointSet.h"

#include <dynslam/frontend/RayNoiseRegistration.h>

#include <algorithm>
#include <cmath>

namespace dynslam::frontend {
namespace {

std::vector<std::int64_t> idsOf(const std::vector<PointPair>& pairs, const std::vector<int>& in) {
  std::vector<std::int64_t> ids;
  ids.reserve(in.size());
  for (int i : in) ids.push_back(pairs[size_t(i)].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

AdaptiveRigidPointSet::AdaptiveRigidPointSet(RigidPointSetParams params, std::uint32_t seed)
    : params_(params), rng_(seed) {}

void AdaptiveRigidPointSet::reset() {
  members_.clear();
  motion_ = {};
  own_rotation_.setIdentity();
  virtual_centroid_.setZero();
}

void AdaptiveRigidPointSet::applyRotationPrior(const std::vector<int>& inliers,
                                               const std::vector<Eigen::Vector3d>& p,
                                               const std::vector<Eigen::Vector3d>& q,
                                               const std::vector<double>& weights,
                                               const Eigen::Matrix3d& cameraRotation,
                                               bool continued) {
  const double sigma = params_.rotation_prior_sigma;
  if (!(sigma > 0) || weights.size() != p.size() || inliers.empty()) return;
  double wSum = 0;
  Eigen::Vector3d pMean = Eigen::Vector3d::Zero(), qMean = Eigen::Vector3d::Zero();
  for (int i : inliers) {
    wSum += weights[size_t(i)];
    pMean += weights[size_t(i)] * p[size_t(i)];
    qMean += weights[size_t(i)] * q[size_t(i)];
  }
  pMean /= wSum;
  qMean /= wSum;
  // Rotation information of the weighted Kabsch fit: about (2/3) sum w |p - mean|^2 per axis.
  double information = 0;
  for (int i : inliers) information += weights[size_t(i)] * (p[size_t(i)] - pMean).squaredNorm();
  const double measuredVariance = 1.5 / std::max(information, 1e-12);
  // Predicted: the set keeps its own rotation (a new one: none), carried into this camera frame.
  const Eigen::Matrix3d own =
      continued ? Eigen::Matrix3d(cameraRotation * own_rotation_ * cameraRotation.transpose())
                : Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d predicted = own * cameraRotation;
  const double gain = sigma * sigma / (sigma * sigma + measuredVariance);
  const Eigen::AngleAxisd correction(predicted.transpose() * motion_.R);
  motion_.R = predicted *
              Eigen::AngleAxisd(gain * correction.angle(), correction.axis()).toRotationMatrix();
  motion_.t = qMean - motion_.R * pMean;
  own_rotation_ = motion_.R * cameraRotation.transpose();
}

/// Each pair's noise, for the precise registration (all empty: depth_sigma_z2 = 0).
struct AdaptiveRigidPointSet::PairNoise {
  std::vector<double> weights;              ///< inverse variance of each pair
  std::vector<double> gates;                ///< noise_gates: each pair's inlier gate
  std::vector<Eigen::Matrix3d> covP, covQ;  ///< pixel_sigma_px: along and across the rays
  bool onRays = false;                      ///< the refinement on the rays applies
};

AdaptiveRigidPointSet::PairNoise AdaptiveRigidPointSet::pairNoise(
    const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
    double focalPx) const {
  PairNoise n;
  n.onRays = params_.pixel_sigma_px > 0 && focalPx > 0 && params_.depth_sigma_z2 > 0;
  if (params_.depth_sigma_z2 > 0)
    for (size_t i = 0; i < p.size(); ++i) {
      const double k = params_.depth_sigma_z2 / std::max(1.0, params_.point_noise_reduction);
      const double sp = 0.001 + k * p[i].z() * p[i].z();
      const double sq = 0.001 + k * q[i].z() * q[i].z();
      n.weights.push_back(1.0 / (sp * sp + sq * sq));
      if (params_.noise_gates)
        n.gates.push_back(
            std::max(params_.ransac.inlier_threshold, 3 * std::sqrt(sp * sp + sq * sq)));
      if (n.onRays) {
        const double across = params_.pixel_sigma_px / focalPx;
        n.covP.push_back(rayCovariance(p[i], sp, across * p[i].z()));
        n.covQ.push_back(rayCovariance(q[i], sq, across * q[i].z()));
      }
    }
  return n;
}

void AdaptiveRigidPointSet::registerPrecisely(const RegistrationResult& r, bool continued,
                                              const PairNoise& n,
                                              const std::vector<Eigen::Vector3d>& p,
                                              const std::vector<Eigen::Vector3d>& q,
                                              const Eigen::Matrix3d& cameraRotation) {
  // pixel_sigma_px: on the rays, refitted on the members that lie within ray_gate_sigmas there
  // (the membership stays RANSAC's, see the params); then rotation_prior_sigma's blend. The
  // blend's translation is fitted on the same gated members: on all of RANSAC's it took back a
  // member the gate had left out (a corner sliding along a car's silhouette;
  // docs/notes/frontend.md, 2026-11-28).
  std::vector<int> fitted = r.inliers;
  motion_ = r.motion;
  if (n.onRays) {
    motion_ = refineOnRays(p, q, n.covP, n.covQ, r.motion, r.inliers);
    std::vector<int> in =
        inliersOnRays(p, q, n.covP, n.covQ, motion_, params_.ray_gate_sigmas, r.inliers);
    if (in.size() >= 3 && in.size() < r.inliers.size()) {
      motion_ = refineOnRays(p, q, n.covP, n.covQ, motion_, in);
      fitted = std::move(in);
    }
  }
  applyRotationPrior(fitted, p, q, n.weights, cameraRotation, continued);
  if (n.onRays && params_.rotation_prior_sigma > 0)
    motion_.t = translationOnRays(p, q, n.covP, n.covQ, motion_.R, fitted);
}

bool AdaptiveRigidPointSet::update(const std::vector<PointPair>& pairs,
                                   const Eigen::Matrix3d& cameraRotation, double focalPx) {
  last_ = {};
  std::vector<Eigen::Vector3d> p, q;
  p.reserve(pairs.size());
  q.reserve(pairs.size());
  std::vector<int> stillTracked;  // pairs of current members
  for (size_t i = 0; i < pairs.size(); ++i) {
    p.push_back(pairs[i].p);
    q.push_back(pairs[i].q);
    if (std::binary_search(members_.begin(), members_.end(), pairs[i].id))
      stillTracked.push_back(int(i));
  }
  const auto minMembers = size_t(std::max(3, params_.min_members));
  const PairNoise noise = pairNoise(p, q, focalPx);

  // Continuation: hypotheses from the surviving members, plus the last motion (an object
  // moves smoothly from one frame to the next), inliers over all pairs.
  if (exists() && int(stillTracked.size()) >= params_.ransac.sample_size) {
    const auto r = registerRansac(p, q, params_.ransac, rng_, stillTracked, {motion_},
                                  noise.weights, noise.gates);
    if (r && r->inliers.size() >= minMembers) {
      std::vector<std::int64_t> ids = idsOf(pairs, r->inliers);
      std::set_difference(ids.begin(), ids.end(), members_.begin(), members_.end(),
                          std::back_inserter(last_.joined));
      std::set_difference(members_.begin(), members_.end(), ids.begin(), ids.end(),
                          std::back_inserter(last_.left));
      members_ = std::move(ids);
      registerPrecisely(*r, true, noise, p, q, cameraRotation);
      virtual_centroid_ = motion_.apply(virtual_centroid_);
      return true;
    }
  }

  // Creation: the largest rigid group among all the object's pairs.
  reset();
  const auto r = registerRansac(p, q, params_.ransac, rng_, {}, {}, noise.weights, noise.gates);
  if (!r || r->inliers.size() < minMembers) return false;
  members_ = idsOf(pairs, r->inliers);
  registerPrecisely(*r, false, noise, p, q, cameraRotation);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i : r->inliers) c += q[size_t(i)];
  virtual_centroid_ = c / double(r->inliers.size());
  last_.created = true;
  return true;
}

core::RigidSet AdaptiveRigidPointSet::toRigidSet(int object_id) const {
  core::RigidSet s;
  s.object_id = object_id;
  s.members = members_;
  s.R = motion_.R;
  s.t = motion_.t;
  s.virtual_centroid = virtual_centroid_;
  return s;
}

}  // namespace dynslam::frontend
