#include "dynslam/evaluation/PoseRelation.h"

#include <cmath>
#include <stdexcept>

namespace dynslam::evaluation {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

PoseRelation parsePoseRelation(const std::string& name) {
  if (name == "trans" || name == "trans_part") return PoseRelation::TranslationPart;
  if (name == "rot" || name == "rot_part") return PoseRelation::RotationPart;
  if (name == "full") return PoseRelation::FullTransformation;
  if (name == "angle_deg") return PoseRelation::AngleDeg;
  if (name == "angle_rad") return PoseRelation::AngleRad;
  throw std::invalid_argument("unknown pose relation '" + name +
                              "' (expected trans, rot, full, angle_deg or angle_rad)");
}

const char* describe(PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart:
      return "translation part";
    case PoseRelation::RotationPart:
      return "rotation part";
    case PoseRelation::FullTransformation:
      return "full transformation";
    case PoseRelation::AngleDeg:
    case PoseRelation::AngleRad:
      return "rotation angle";
  }
  return "?";
}

const char* unitOf(PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart:
      return "m";
    case PoseRelation::AngleDeg:
      return "deg";
    case PoseRelation::AngleRad:
      return "rad";
    case PoseRelation::RotationPart:
    case PoseRelation::FullTransformation:
      return "";
  }
  return "";
}

Eigen::Matrix4d relativePose(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
  Eigen::Matrix4d a_inv = Eigen::Matrix4d::Identity();
  const Eigen::Matrix3d rt = a.block<3, 3>(0, 0).transpose();
  a_inv.block<3, 3>(0, 0) = rt;
  a_inv.block<3, 1>(0, 3) = -rt * a.block<3, 1>(0, 3);
  return a_inv * b;
}

double rotationAngle(const Eigen::Matrix3d& m) {
  // Quaternion (x, y, z, w) from the largest of the diagonal entries and the trace, the
  // numerically safe branch; then normalised (scipy does the same for non-orthonormal input).
  const double trace = m(0, 0) + m(1, 1) + m(2, 2);
  const double decision[4] = {m(0, 0), m(1, 1), m(2, 2), trace};
  int choice = 0;
  for (int k = 1; k < 4; ++k)
    if (decision[k] > decision[choice]) choice = k;
  double q[4];
  if (choice != 3) {
    const int i = choice, j = (i + 1) % 3, k = (j + 1) % 3;
    q[i] = 1.0 - trace + 2.0 * m(i, i);
    q[j] = m(j, i) + m(i, j);
    q[k] = m(k, i) + m(i, k);
    q[3] = m(k, j) - m(j, k);
  } else {
    q[0] = m(2, 1) - m(1, 2);
    q[1] = m(0, 2) - m(2, 0);
    q[2] = m(1, 0) - m(0, 1);
    q[3] = 1.0 + trace;
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double vec_norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) / norm;
  const double w = std::abs(q[3]) / norm;
  return 2.0 * std::atan2(vec_norm, w);
}

double poseError(const Eigen::Matrix4d& e, PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart:
      return e.block<3, 1>(0, 3).norm();
    case PoseRelation::RotationPart:
      return (e.block<3, 3>(0, 0) - Eigen::Matrix3d::Identity()).norm();
    case PoseRelation::FullTransformation:
      return (e - Eigen::Matrix4d::Identity()).norm();
    case PoseRelation::AngleRad:
      return rotationAngle(e.block<3, 3>(0, 0));
    case PoseRelation::AngleDeg:  // numpy's rad2deg multiplies by the constant 180/pi.
      return rotationAngle(e.block<3, 3>(0, 0)) * (180.0 / kPi);
  }
  return 0.0;
}

}  // namespace dynslam::evaluation
