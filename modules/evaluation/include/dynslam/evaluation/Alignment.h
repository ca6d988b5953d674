#pragma once
// Aligning an estimate to its reference before computing errors, as evo_ape / evo_rpe do with
// --align, --correct_scale and --align_origin.
#include <dynslam/core/Trajectory.h>
#include <dynslam/evaluation/Umeyama.h>

#include <Eigen/Geometry>

#include <string>

namespace dynslam::evaluation {

enum class AlignmentMode {
  None,  ///< leave the estimate as it is
  Se3,   ///< Umeyama without scale (evo -a)
  Sim3,  ///< Umeyama with scale (evo -as)
};

/// "none", "se3" or "sim3"; throws std::invalid_argument otherwise.
AlignmentMode parseAlignmentMode(const std::string& name);
const char* toString(AlignmentMode mode);

/// What alignTrajectory applied to the estimate.
struct AlignmentResult {
  AlignmentMode mode = AlignmentMode::None;
  /// The Umeyama transform (identity unless mode != None).
  SimilarityTransform umeyama;
  bool origin_aligned = false;
  /// ref_0 * est_0^-1 (identity unless origin_aligned).
  Eigen::Isometry3d origin_transform = Eigen::Isometry3d::Identity();
};

/// Aligns `est` in place to `ref` (paired pose k with pose k, same length), using the
/// positions only, like evo: first the Umeyama fit of `mode` (scale applied to the positions,
/// then the rigid part to the whole poses), then, when `align_origin`, the rigid transform that
/// puts the first estimated pose onto the first reference pose.
AlignmentResult alignTrajectory(const core::Trajectory& ref, core::Trajectory& est,
                                AlignmentMode mode, bool align_origin);

/// Applies x -> scale * R * x + t to the positions and R to the orientations (evo's
/// PosePath3D.scale() followed by transform()).
void applySimilarity(const SimilarityTransform& transform, core::Trajectory& trajectory);

}  // namespace dynslam::evaluation
