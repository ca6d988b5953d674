#include "dynslam/sim/GroundTruthSpline.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// ZYX angles of R (the inverse of rotationFromYawPitchRoll away from pitch = +-90 deg).
Eigen::Vector3d yawPitchRollOf(const Eigen::Matrix3d& R) {
  return {std::atan2(R(1, 0), R(0, 0)), std::asin(std::clamp(-R(2, 0), -1.0, 1.0)),
          std::atan2(R(2, 1), R(2, 2))};
}

/// Uniform cubic B-spline basis at u in [0, 1] (as SplineTrajectory evaluates it).
Eigen::Vector4d basisAt(double u) {
  const double u2 = u * u, u3 = u2 * u, v = 1.0 - u;
  return {v * v * v / 6.0, (3 * u3 - 6 * u2 + 4) / 6.0, (-3 * u3 + 3 * u2 + 3 * u + 1) / 6.0,
          u3 / 6.0};
}

void checkPoses(const core::Trajectory& poses, double knot_interval) {
  if (poses.size() < 2)
    throw std::invalid_argument("fitSplineToPoses: needs at least 2 poses, got " +
                                std::to_string(poses.size()));
  if (!(knot_interval > 0) || !std::isfinite(knot_interval))
    throw std::invalid_argument("fitSplineToPoses: knot_interval must be a positive number of s");
  for (size_t i = 1; i < poses.size(); ++i)
    if (!(poses[i].t > poses[i - 1].t))
      throw std::invalid_argument("fitSplineToPoses: pose times must increase strictly (pose " +
                                  std::to_string(i) + ")");
}

}  // namespace

SplineTrajectory fitSplineToPoses(const core::Trajectory& poses, double knot_interval) {
  checkPoses(poses, knot_interval);
  const double t0 = poses.front().t, dt = knot_interval;
  const auto segments =
      static_cast<int>(std::max(1.0, std::ceil((poses.back().t - t0) / dt - 1e-9)));
  const int n = segments + 3;

  // Per pose: position and unwrapped angles, the fitting targets of the six channels.
  Eigen::MatrixXd targets(poses.size(), 6);
  for (size_t j = 0; j < poses.size(); ++j) {
    Eigen::Vector3d ypr = yawPitchRollOf(poses[j].T_world_body.rotation());
    if (std::abs(ypr[1]) > kPi / 2 - 5 * kPi / 180)
      throw std::invalid_argument("fitSplineToPoses: pose " + std::to_string(j) +
                                  " is pitched within 5 deg of vertical (ZYX angles degenerate)");
    if (j > 0)
      for (int a : {0, 2})  // yaw and roll wrap at +-pi; follow the previous pose
        ypr[a] += 2 * kPi * std::round((targets(j - 1, 3 + a) - ypr[a]) / (2 * kPi));
    targets.row(j) << poses[j].T_world_body.translation().transpose(), ypr.transpose();
  }

  // Normal equations of the data terms plus the faint second-difference penalty.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 6);
  for (size_t j = 0; j < poses.size(); ++j) {
    const double s = (poses[j].t - t0) / dt;
    const int k = std::min(static_cast<int>(std::floor(s)), n - 4);
    const Eigen::Vector4d b = basisAt(s - k);
    for (int r = 0; r < 4; ++r) {
      rhs.row(k + r) += b[r] * targets.row(j);
      for (int c = 0; c < 4; ++c) entries.emplace_back(k + r, k + c, b[r] * b[c]);
    }
  }
  const double penalty = 1e-6 * static_cast<double>(poses.size()) / n;
  const double second_difference[3] = {1, -2, 1};
  for (int i = 0; i + 2 < n; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        entries.emplace_back(i + r, i + c, penalty * second_difference[r] * second_difference[c]);
  Eigen::SparseMatrix<double> normal(n, n);
  normal.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("fitSplineToPoses: the least-squares system is singular");
  const Eigen::MatrixXd controls = solver.solve(rhs);

  std::vector<Eigen::Vector3d> positions(n), angles(n);
  for (int i = 0; i < n; ++i) {
    positions[i] = controls.row(i).head<3>().transpose();
    angles[i] = controls.row(i).tail<3>().transpose();
  }
  return SplineTrajectory(std::move(positions), std::move(angles), dt, t0);
}

SplineFitError splineFitError(const SplineTrajectory& spline, const core::Trajectory& sensor_poses,
                              const Eigen::Isometry3d& T_body_sensor) {
  std::vector<double> position, rotation;
  for (const auto& p : sensor_poses) {
    const Eigen::Isometry3d T = spline.sample(p.t).T_world_body * T_body_sensor;
    position.push_back((T.translation() - p.T_world_body.translation()).norm());
    rotation.push_back(
        Eigen::AngleAxisd(T.rotation().transpose() * p.T_world_body.rotation()).angle());
  }
  SplineFitError e;
  if (position.empty()) return e;
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  e.median_position = median(position);
  e.median_rotation = median(rotation);
  e.max_position = *std::max_element(position.begin(), position.end());
  e.max_rotation = *std::max_element(rotation.begin(), rotation.end());
  return e;
}

}  // namespace dynslam::sim
