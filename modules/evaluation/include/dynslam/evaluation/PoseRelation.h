#pragma once
// Which part of an error pose E becomes the scalar error (evo.core.metrics.PoseRelation), and
// the SE(3) helpers evo's definitions rest on.
#include <Eigen/Geometry>

#include <string>

namespace dynslam::evaluation {

enum class PoseRelation {
  TranslationPart,     ///< |t(E)|, metres
  RotationPart,        ///< |R(E) - I|_F, no unit
  FullTransformation,  ///< |E - I_4x4|_F, no unit
  AngleDeg,            ///< rotation angle of R(E), degrees
  AngleRad,            ///< rotation angle of R(E), radians
};

/// Accepts the dynslam names (trans, rot, full, angle_deg, angle_rad) and evo's (trans_part,
/// rot_part); throws std::invalid_argument otherwise.
PoseRelation parsePoseRelation(const std::string& name);
/// evo's wording: "translation part", "rotation part", "full transformation", "rotation angle".
const char* describe(PoseRelation relation);
/// "m", "deg", "rad" or "" (dimension-less).
const char* unitOf(PoseRelation relation);

/// a^-1 * b with the inverse taken as [R^T, -R^T t], as evo's relative_se3 does (also for the
/// not exactly orthonormal rotations of KITTI files).
Eigen::Matrix4d relativePose(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b);

/// Rotation angle in [0, pi] of a 3x3 matrix, computed like scipy's
/// Rotation.from_matrix(m).as_rotvec() (largest-component quaternion extraction, normalised),
/// which is what evo's so3_log_angle uses.
double rotationAngle(const Eigen::Matrix3d& rotation);

/// The scalar error of one error pose E under `relation`.
double poseError(const Eigen::Matrix4d& error_pose, PoseRelation relation);

}  // namespace dynslam::evaluation
