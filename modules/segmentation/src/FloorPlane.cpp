#include "dynslam/segmentation/FloorPlane.h"

#include "dynslam/segmentation/DepthSampling.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

namespace dynslam::segmentation {
namespace {

Eigen::Vector3d backProject(int u, int v, double z, const core::CameraIntrinsics& k) {
  return {(u - k.cx) * z / k.fx, (v - k.cy) * z / k.fy, z};
}

// The plane through three points, oriented with the camera above it; nothing when they are
// nearly collinear.
std::optional<Plane> planeThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c) {
  Eigen::Vector3d n = (b - a).cross(c - a);
  const double len = n.norm();
  if (!(len > 1e-9)) return std::nullopt;
  Plane p;
  p.n = n / len;
  p.d = -p.n.dot(a);
  if (p.d < 0) {
    p.n = -p.n;
    p.d = -p.d;
  }
  return p;
}

bool plausible(const Plane& p, const FloorPlaneParams& params) {
  const double cosTilt = -p.n.y();  // the floor's normal points up: -y in the camera frame
  return cosTilt >= std::cos(params.max_tilt_deg * M_PI / 180) && p.d >= params.min_height &&
         p.d <= params.max_height;
}

// Least-squares plane of the points (smallest eigenvector of their scatter), oriented as above.
Plane refit(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  Plane plane;
  plane.n = eig.eigenvectors().col(0);
  plane.d = -plane.n.dot(mean);
  if (plane.d < 0) {
    plane.n = -plane.n;
    plane.d = -plane.d;
  }
  return plane;
}

}  // namespace

std::optional<Plane> fitFloorPlane(const cv::Mat& depth, const core::CameraIntrinsics& k,
                                   const FloorPlaneParams& params) {
  if (depth.empty() || !(k.fx > 0 && k.fy > 0)) return std::nullopt;
  std::vector<Eigen::Vector3d> points;
  points.reserve(size_t(params.samples));
  const cv::Rect2d lowerHalf(0, depth.rows / 2.0, depth.cols, depth.rows / 2.0);
  forEachGridPoint(depth, lowerHalf, params.samples,
                   [&](cv::Point p, float z) { points.push_back(backProject(p.x, p.y, z, k)); });
  if (points.size() < 3) return std::nullopt;
  std::mt19937 rng(params.seed);
  std::uniform_int_distribution<size_t> pick(0, points.size() - 1);
  const auto countInliers = [&](const Plane& p) {
    int n = 0;
    for (const auto& q : points) n += std::abs(p.distance(q)) < params.inlier_distance;
    return n;
  };
  std::optional<Plane> best;
  int bestCount = 0;
  for (int it = 0; it < params.iterations; ++it) {
    const auto p = planeThrough(points[pick(rng)], points[pick(rng)], points[pick(rng)]);
    if (!p || !plausible(*p, params)) continue;
    const int count = countInliers(*p);
    if (count > bestCount) bestCount = count, best = p;
  }
  if (!best || bestCount < params.min_inlier_share * double(points.size())) return std::nullopt;
  std::vector<Eigen::Vector3d> inliers;
  for (const auto& q : points)
    if (std::abs(best->distance(q)) < params.inlier_distance) inliers.push_back(q);
  const Plane refined = refit(inliers);
  return plausible(refined, params) ? refined : *best;
}

void dropFloorPixels(core::ObjectMask& mask, const cv::Mat& depth, const core::CameraIntrinsics& k,
                     const Plane& floor, double margin) {
  if (!mask.valid || mask.mask.empty()) return;
  for (int y = 0; y < mask.roi.height; ++y) {
    uint8_t* row = mask.mask.ptr<uint8_t>(y);
    const float* z = depth.ptr<float>(mask.roi.y + y) + mask.roi.x;
    for (int x = 0; x < mask.roi.width; ++x)
      if (row[x] && floor.distance(backProject(mask.roi.x + x, mask.roi.y + y, z[x], k)) < margin)
        row[x] = 0;
  }
}

}  // namespace dynslam::segmentation
