#pragma once
// The adaptive rigid point set of one dynamic object (method.md section 4). The first frame in
// which the object has enough matched 3-D pairs, a coarse 4-point RANSAC over all its pairs
// picks the largest group that moves as one rigid body (on a person, typically the torso) and
// the precise registration refits the motion on all of it. From then on, each frame:
//  - the hypotheses are drawn from the pairs of the current members that are still tracked, and
//    inliers are counted over ALL the object's pairs, so a point that now moves rigidly with the
//    set joins it (paper Fig. 5, P2) and a member that broke away is dropped (P1);
//  - the precise registration refits (R, t) on the new inlier set;
//  - the virtual centroid (the members' centroid when the set was created) is carried forward
//    with that motion, c_{k+1} = R c_k + t. Members come and go, so the real centroid of the
//    members jumps whenever one does; the virtual centroid is a fixed point of the body and
//    gives the object a translation that is continuous across membership changes.
// When fewer than sample_size members are still tracked, or the continued set would have fewer
// than min_members points, the set is created afresh (new members, new virtual centroid).
// A rigid object (car) goes through the same steps with all its features as candidates.
#include <dynslam/core/Features.h>
#include <dynslam/frontend/RigidRegistration.h>

#include <cstdint>
#include <random>
#include <vector>

namespace dynslam::frontend {

/// One feature seen with depth in the previous frame (p) and in this one (q), each in that
/// frame's camera coordinates.
struct PointPair {
  std::int64_t id = -1;  ///< core::Feature::id
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
};

struct RigidPointSetParams {
  RansacParams ransac;  ///< 4 pairs, 100 iterations, tau = 0.03 m (method.md)
  int min_members = 5;  ///< fewer inliers than this: no rigid set on the object this frame
  /// Depth noise sigma(z) = depth_sigma_z2 z^2 (1/m): the precise registration weighs each
  /// inlier by the inverse variance of its pair (a car's far points are metres apart in noise
  /// from its near ones). 0: equal weights, the method's plain least squares.
  double depth_sigma_z2 = 0.0015;
  /// Points whose depth noise exceeds tau (far ones) get the inlier gate 3 sigma of their
  /// pair instead of tau (sigma of a point: depth_sigma_z2 z^2 / point_noise_reduction, the
  /// reduction of the window depth); false: tau for every pair, the method.
  bool noise_gates = true;
  double point_noise_reduction = 4.0;
  /// rad per frame; > 0: the set's own rotation (the camera's removed) is predicted to stay what
  /// it was (none for a new set), with this sigma, and the precise registration's rotation is
  /// blended with the prediction by their variances (the registration's from the depth noise
  /// and the members' spread); the translation then follows from the weighted centroids. Not
  /// the method (0: off). Needs depth_sigma_z2 > 0 and the camera's rotation in update().
  double rotation_prior_sigma = 0.0087;
  /// px; > 0: the precise registration is refined with each point's noise along its ray (the
  /// depth's, as above) and across it (this pixel sigma at the point's depth), then refitted on
  /// the members within ray_gate_sigmas of that motion by the same noise (RayNoiseRegistration.h).
  /// The membership stays RANSAC's: made the members, the gate's smaller sets were created afresh
  /// more often, each time with a new virtual centroid (docs/notes/frontend.md, 2026-11-28). Not
  /// the method (0: off, Kabsch on the RANSAC inliers). Needs depth_sigma_z2 > 0 and the focal
  /// length in update().
  double pixel_sigma_px = 0.3;
  double ray_gate_sigmas = 3.5;
};

/// What the last update did to the membership.
struct RigidSetUpdate {
  bool created = false;  ///< a new set (first one, or the old one could not be continued)
  std::vector<std::int64_t> joined, left;  ///< members admitted / dropped by a continuation
};

class AdaptiveRigidPointSet {
 public:
  explicit AdaptiveRigidPointSet(RigidPointSetParams params = {}, std::uint32_t seed = 1);

  /// One frame of the object: its pairs from the previous frame to this one, and the camera's
  /// rotation over it (static points: q = R p + t; used by rotation_prior_sigma only), and the
  /// camera's focal length in pixels (used by pixel_sigma_px only). Returns true when the object
  /// has a rigid set after the update (members, motion and virtual centroid valid).
  bool update(const std::vector<PointPair>& pairs,
              const Eigen::Matrix3d& cameraRotation = Eigen::Matrix3d::Identity(),
              double focalPx = 0);
  /// Forgets the set (the object stopped, or left the view).
  void reset();

  bool exists() const { return !members_.empty(); }
  const std::vector<std::int64_t>& members() const { return members_; }  ///< ascending ids
  const RigidMotion& motion() const { return motion_; }  ///< previous frame -> this frame
  const Eigen::Vector3d& virtualCentroid() const { return virtual_centroid_; }
  const RigidSetUpdate& lastUpdate() const { return last_; }

  /// The set as the frame carries it.
  core::RigidSet toRigidSet(int object_id) const;

 private:
  RigidPointSetParams params_;
  std::mt19937 rng_;
  std::vector<std::int64_t> members_;
  RigidMotion motion_;
  /// The set's own rotation over the last frame, the camera's removed (motion_.R times the
  /// camera rotation's inverse), in the current camera frame; the prior's prediction.
  Eigen::Matrix3d own_rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d virtual_centroid_ = Eigen::Vector3d::Zero();

  /// rotation_prior_sigma: blends motion_'s rotation with the predicted one (see the params)
  /// and keeps the result's own rotation for the next frame's prediction.
  void applyRotationPrior(const std::vector<int>& inliers, const std::vector<Eigen::Vector3d>& p,
                          const std::vector<Eigen::Vector3d>& q, const std::vector<double>& weights,
                          const Eigen::Matrix3d& cameraRotation, bool continued);
  RigidSetUpdate last_;

  struct PairNoise;  // RigidPointSet.cpp
  PairNoise pairNoise(const std::vector<Eigen::Vector3d>& p, const std::vector<Eigen::Vector3d>& q,
                      double focalPx) const;
  /// motion_ from RANSAC's result `r`: the precise registration (on the rays with
  /// pixel_sigma_px), then the rotation prior.
  void registerPrecisely(const RegistrationResult& r, bool continued, const PairNoise& n,
                         const std::vector<Eigen::Vector3d>& p,
                         const std::vector<Eigen::Vector3d>& q,
                         const Eigen::Matrix3d& cameraRotation);
};

}  // namespace dynslam::frontend
