#include "dynslam/evaluation/Alignment.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <stdexcept>

namespace dynslam::evaluation {

AlignmentMode parseAlignmentMode(const std::string& name) {
  if (name == "none") return AlignmentMode::None;
  if (name == "se3") return AlignmentMode::Se3;
  if (name == "sim3") return AlignmentMode::Sim3;
  throw std::invalid_argument("unknown alignment '" + name + "' (expected none, se3 or sim3)");
}

const char* toString(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::None:
      return "none";
    case AlignmentMode::Se3:
      return "se3";
    case AlignmentMode::Sim3:
      return "sim3";
  }
  return "?";
}

void applySimilarity(const SimilarityTransform& transform, core::Trajectory& trajectory) {
  for (auto& pose : trajectory) {
    Eigen::Matrix4d m = pose.T_world_body.matrix();
    // evo scales the positions first, then left-multiplies the rigid part.
    const Eigen::Vector3d scaled = transform.scale * m.block<3, 1>(0, 3);
    m.block<3, 3>(0, 0) = transform.rotation * m.block<3, 3>(0, 0);
    m.block<3, 1>(0, 3) = transform.rotation * scaled + transform.translation;
    pose.T_world_body.matrix() = m;
  }
}

AlignmentResult alignTrajectory(const core::Trajectory& ref, core::Trajectory& est,
                                AlignmentMode mode, bool align_origin) {
  if (ref.size() != est.size())
    throw EvaluationError("alignment needs paired trajectories of the same length");
  if (ref.empty()) throw EvaluationError("cannot align empty trajectories");

  AlignmentResult result;
  result.mode = mode;
  if (mode != AlignmentMode::None) {
    const Eigen::Index n = static_cast<Eigen::Index>(ref.size());
    Eigen::Matrix3Xd from(3, n), to(3, n);
    for (Eigen::Index k = 0; k < n; ++k) {
      from.col(k) = est[static_cast<std::size_t>(k)].T_world_body.translation();
      to.col(k) = ref[static_cast<std::size_t>(k)].T_world_body.translation();
    }
    result.umeyama = umeyamaAlignment(from, to, mode == AlignmentMode::Sim3);
    applySimilarity(result.umeyama, est);
  }
  if (align_origin) {
    // ref_0 * se3_inverse(est_0), the inverse taken by transposition like evo's.
    const Eigen::Matrix4d est0 = est.front().T_world_body.matrix();
    Eigen::Matrix4d est0_inv = Eigen::Matrix4d::Identity();
    est0_inv.block<3, 3>(0, 0) = est0.block<3, 3>(0, 0).transpose();
    est0_inv.block<3, 1>(0, 3) = -est0.block<3, 3>(0, 0).transpose() * est0.block<3, 1>(0, 3);
    const Eigen::Matrix4d to_ref_origin = ref.front().T_world_body.matrix() * est0_inv;
    for (auto& pose : est) pose.T_world_body.matrix() = to_ref_origin * pose.T_world_body.matrix();
    result.origin_aligned = true;
    result.origin_transform.matrix() = to_ref_origin;
  }
  return result;
}

}  // namespace dynslam::evaluation
