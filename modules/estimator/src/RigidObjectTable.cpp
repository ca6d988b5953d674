#include "dynslam/estimator/RigidObjectTable.h"

#include "dynslam/estimator/StateBlocks.h"

#include <Eigen/Geometry>  // Eigen::umeyama

namespace dynslam::estimator {
namespace {

Eigen::Isometry3d poseOf(const std::array<double, 7>& block) { return poseFromBlock(block.data()); }

/// The previous pose moved by the last interval's motion (object frame, L_a^-1 L_b), or kept
/// when there is only one.
Eigen::Isometry3d predictPose(const RigidObject& object) {
  const auto last = object.poses.rbegin();
  const Eigen::Isometry3d L1 = poseOf(last->second);
  if (object.poses.size() < 2) return L1;
  const Eigen::Isometry3d L0 = poseOf(std::next(last)->second);
  return nearestRigid(L1 * (L0.inverse() * L1));
}

/// The rigid transform T minimising sum |T from_i - to_i|^2 (Umeyama, no scale), when there
/// are enough points.
std::optional<Eigen::Isometry3d> kabsch(const std::vector<Eigen::Vector3d>& from,
                                        const std::vector<Eigen::Vector3d>& to) {
  if (int(from.size()) < RigidObjectTable::kMinFeatures) return std::nullopt;
  Eigen::Matrix3Xd src(3, from.size()), dst(3, to.size());
  for (size_t i = 0; i < from.size(); ++i) {
    src.col(i) = from[i];
    dst.col(i) = to[i];
  }
  Eigen::Isometry3d T;
  T.matrix() = Eigen::umeyama(src, dst, false);
  if (!T.matrix().allFinite()) return std::nullopt;
  return nearestRigid(T);
}

/// A new object's first pose: the caller's guess, else the centroid of its measured points
/// (`withDepth` of them) with the world's axes.
Eigen::Isometry3d firstPose(const std::vector<RigidObjectFeature>& features,
                            const std::vector<Eigen::Vector3d>& measured, int withDepth,
                            const std::optional<Eigen::Isometry3d>& guess) {
  if (guess && guess->matrix().allFinite()) return nearestRigid(*guess);
  Eigen::Isometry3d L = Eigen::Isometry3d::Identity();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < features.size(); ++i)
    if (features[i].depth > 0) centroid += measured[i];
  L.translation() = centroid / withDepth;
  return L;
}

}  // namespace

Eigen::Isometry3d RigidObjectTable::fitPose(RigidObject& object,
                                            const std::vector<RigidObjectFeature>& features,
                                            const std::vector<Eigen::Vector3d>& measured) {
  // Kabsch on the features already in the object frame that have a depth now; then once more
  // without the points that moved away from where the object model puts them.
  std::vector<std::int64_t> ids;
  std::vector<Eigen::Vector3d> from, to;
  for (size_t i = 0; i < features.size(); ++i) {
    const auto p = object.points.find(features[i].id);
    if (p == object.points.end() || !(features[i].depth > 0)) continue;
    ids.push_back(features[i].id);
    from.emplace_back(p->second.m_obj);
    to.push_back(measured[i]);
  }
  Eigen::Isometry3d L = predictPose(object);
  if (const auto fit = kabsch(from, to)) {
    L = *fit;
    std::vector<Eigen::Vector3d> keptFrom, keptTo;
    for (size_t i = 0; i < from.size(); ++i) {
      if ((L * from[i] - to[i]).norm() <= max_point_offset_) {
        keptFrom.push_back(from[i]);
        keptTo.push_back(to[i]);
      } else {
        // A point that broke away (an arm on a walking person's torso set, a feature that
        // slid off): it starts again from this measurement.
        object.points.erase(ids[i]);
      }
    }
    if (const auto refit = kabsch(keptFrom, keptTo)) L = *refit;
  }
  return L;
}

bool RigidObjectTable::observe(int object_id, std::int64_t keyframe,
                               const std::vector<RigidObjectFeature>& features,
                               const Eigen::Isometry3d& T_world_camera, const PinholeCamera& camera,
                               const std::optional<Eigen::Isometry3d>& first_pose_guess) {
  if (int(features.size()) < kMinFeatures) return false;
  std::vector<Eigen::Vector3d> measured(features.size());  // world points; depth 0: unused
  int withDepth = 0;
  for (size_t i = 0; i < features.size(); ++i)
    if (features[i].depth > 0) {
      measured[i] = T_world_camera * (camera.bearing(features[i].pixel) * features[i].depth);
      ++withDepth;
    }

  const auto found = objects_.find(object_id);
  Eigen::Isometry3d L = Eigen::Isometry3d::Identity();
  if (found == objects_.end() || found->second.poses.empty()) {
    if (withDepth < kMinFeatures) return false;
    L = firstPose(features, measured, withDepth, first_pose_guess);
  } else {
    L = fitPose(found->second, features, measured);
  }

  RigidObject& object = objects_[object_id];
  poseToBlock(L, object.poses[keyframe].data());
  const Eigen::Isometry3d L_inv = L.inverse();
  for (size_t i = 0; i < features.size(); ++i) {
    const RigidObjectFeature& f = features[i];
    auto p = object.points.find(f.id);
    if (p == object.points.end()) {
      if (!(f.depth > 0)) continue;  // a new point needs its depth to be placed
      p = object.points.emplace(f.id, RigidObjectPoint{}).first;
      Eigen::Map<Eigen::Vector3d>(p->second.m_obj) = L_inv * measured[i];
    }
    p->second.observations[keyframe] = {f.pixel, f.depth};
  }
  return true;
}

void RigidObjectTable::recentre(std::int64_t keyframe) {
  for (auto& [id, object] : objects_) {
    if (!object.poses.count(keyframe)) continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    int n = 0;
    for (const auto& [fid, p] : object.points)
      if (p.observations.count(keyframe)) {
        centroid += Eigen::Vector3d(p.m_obj);
        ++n;
      }
    if (n == 0) continue;
    centroid /= n;
    // L -> L G, m_obj -> G^-1 m_obj with G = translation(centroid): the same world points.
    for (auto& [kf, block] : object.poses) {
      Eigen::Isometry3d L = poseOf(block);
      L.translation() += L.linear() * centroid;
      poseToBlock(L, block.data());
    }
    for (auto& [fid, p] : object.points) Eigen::Map<Eigen::Vector3d>(p.m_obj) -= centroid;
  }
}

void RigidObjectTable::removeKeyframe(std::int64_t keyframe) {
  for (auto o = objects_.begin(); o != objects_.end();) {
    RigidObject& object = o->second;
    object.poses.erase(keyframe);
    for (auto p = object.points.begin(); p != object.points.end();) {
      p->second.observations.erase(keyframe);
      p = p->second.observations.empty() ? object.points.erase(p) : std::next(p);
    }
    o = object.poses.empty() ? objects_.erase(o) : std::next(o);
  }
}

}  // namespace dynslam::estimator
