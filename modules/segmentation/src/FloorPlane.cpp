#include "dynslam/segmentation/FloorPlane.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <random>

namespace dynslam::segmentation {
namespace {

struct Sample {
  Eigen::Vector3d P;
  double tolerance;  // m: inlier_m + 2 sigma(z)
};

std::vector<Sample> gridSamples(const cv::Mat& depth, const core::CameraIntrinsics& K,
                                const std::vector<cv::Rect>& exclude, const FloorPlaneParams& p) {
  std::vector<Sample> samples;
  const int step = std::max(1, p.sample_stride_px);
  for (int v = step / 2; v < depth.rows; v += step) {
    for (int u = step / 2; u < depth.cols; u += step) {
      const double z = depth.at<float>(v, u);
      if (!(z > 0) || z > p.max_depth_m) continue;
      const cv::Point pixel(u, v);
      if (std::any_of(exclude.begin(), exclude.end(),
                      [&](const cv::Rect& r) { return r.contains(pixel); }))
        continue;
      const Eigen::Vector3d P((u - K.cx) / K.fx * z, (v - K.cy) / K.fy * z, z);
      samples.push_back({P, p.inlier_m + 2 * p.depth_sigma_z2 * z * z});
    }
  }
  return samples;
}

// The plane through three points with its normal turned towards `up`; nullopt when they are
// (nearly) collinear or the normal leans more than the limit.
std::optional<FloorPlane> planeThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const Eigen::Vector3d& c, const Eigen::Vector3d& up,
                                       double minCos) {
  Eigen::Vector3d n = (b - a).cross(c - a);
  const double norm = n.norm();
  if (norm < 1e-9) return std::nullopt;
  n /= norm;
  if (n.dot(up) < 0) n = -n;
  if (n.dot(up) < minCos) return std::nullopt;
  FloorPlane plane;
  plane.normal = n;
  plane.offset = -n.dot(a);
  if (plane.offset <= 0) return std::nullopt;  // at or above the camera: a ceiling, not a floor
  return plane;
}

// Least squares on the inliers, each weighted by its depth noise (1 / tolerance^2: the far
// samples' noise is 10-100 times the near ones' and would tilt the plane): the normal is the
// weighted covariance's smallest eigenvector.
FloorPlane refit(const std::vector<const Sample*>& inliers, const Eigen::Vector3d& up) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double weights = 0;
  for (const auto* s : inliers) {
    const double w = 1 / (s->tolerance * s->tolerance);
    mean += w * s->P;
    weights += w;
  }
  mean /= weights;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto* s : inliers)
    cov += (s->P - mean) * (s->P - mean).transpose() / (s->tolerance * s->tolerance);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d n = eig.eigenvectors().col(0);
  if (n.dot(up) < 0) n = -n;
  FloorPlane plane;
  plane.normal = n;
  plane.offset = -n.dot(mean);
  plane.inliers = int(inliers.size());
  return plane;
}

}  // namespace

Eigen::Vector3d upInCamera(const core::Frame& frame) {
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  int n = 0;
  for (const auto& s : frame.imu)
    if (s.has_acc && s.acc.allFinite()) {
      acc += s.acc;
      ++n;
    }
  if (n == 0 || acc.norm() < 1e-6) return Eigen::Vector3d(0, -1, 0);
  const Eigen::Matrix3d R_CI = frame.T_body_camera.linear().transpose() * frame.T_body_imu.linear();
  return (R_CI * acc).normalized();
}

std::optional<FloorPlane> fitFloorPlane(const cv::Mat& depth, const core::CameraIntrinsics& K,
                                        const std::vector<cv::Rect>& exclude,
                                        const Eigen::Vector3d& up, const FloorPlaneParams& p) {
  if (depth.empty() || depth.type() != CV_32FC1) return std::nullopt;
  const std::vector<Sample> samples = gridSamples(depth, K, exclude, p);
  if (int(samples.size()) < std::max(3, p.min_inliers)) return std::nullopt;
  const double minCos = std::cos(p.max_tilt_deg * M_PI / 180);

  std::mt19937 rng(20261124u);
  std::uniform_int_distribution<size_t> pick(0, samples.size() - 1);
  std::optional<FloorPlane> best;
  for (int it = 0; it < p.iterations; ++it) {
    const auto plane =
        planeThrough(samples[pick(rng)].P, samples[pick(rng)].P, samples[pick(rng)].P, up, minCos);
    if (!plane) continue;
    int count = 0;
    for (const auto& s : samples) count += std::abs(plane->height(s.P)) < s.tolerance;
    if (!best || count > best->inliers) {
      best = plane;
      best->inliers = count;
    }
  }
  if (!best || best->inliers < p.min_inliers) return std::nullopt;

  // The hypothesis's inliers lean with its tilt; choosing them again from each refit converges
  // within a few rounds (one refit left the plane centimetres off: docs/notes/perception.md,
  // 2026-11-28).
  FloorPlane refined = *best;
  for (int round = 0; round < 8; ++round) {
    std::vector<const Sample*> inliers;
    for (const auto& s : samples)
      if (std::abs(refined.height(s.P)) < s.tolerance) inliers.push_back(&s);
    if (int(inliers.size()) < p.min_inliers) break;
    const FloorPlane next = refit(inliers, up);
    if (next.normal.dot(up) < minCos) break;
    refined = next;
  }
  return refined;
}

}  // namespace dynslam::segmentation
