#include "dynslam/sim/FloorPlane.h"

#include "dynslam/sim/Random.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace dynslam::sim {
namespace {

struct Score {
  std::size_t inliers = 0, below = 0;
};

Score score(const Plane& plane, const std::vector<Eigen::Vector3d>& points, double inlier_distance,
            double below_margin) {
  Score s;
  for (const auto& p : points) {
    const double h = plane.height(p);
    s.inliers += std::abs(h) <= inlier_distance;
    s.below += h < -below_margin;
  }
  return s;
}

/// Least-squares plane (smallest principal axis) of the points within `distance` of `plane`.
Plane refine(const Plane& plane, const std::vector<Eigen::Vector3d>& points, double distance) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  std::size_t count = 0;
  for (const auto& p : points)
    if (std::abs(plane.height(p)) <= distance) {
      mean += p;
      second += p * p.transpose();
      ++count;
    }
  if (count < 3) return plane;
  mean /= static_cast<double>(count);
  const Eigen::Matrix3d covariance = second / static_cast<double>(count) - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  Plane out;
  out.normal = eigen.eigenvectors().col(0);  // eigenvalues ascend
  if (out.normal.dot(plane.normal) < 0) out.normal = -out.normal;
  out.offset = out.normal.dot(mean);
  return out;
}

}  // namespace

PointGrid backProject(const cv::Mat& depth, const core::CameraIntrinsics& k,
                      const Eigen::Isometry3d& T_world_camera, int step, double max_depth) {
  PointGrid grid;
  grid.rows = (depth.rows + step - 1) / step;
  grid.cols = (depth.cols + step - 1) / step;
  grid.points.resize(static_cast<std::size_t>(grid.rows) * grid.cols);
  grid.valid.resize(grid.points.size());
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const int y = r * step, x = c * step;
      const double z = depth.at<float>(y, x);
      const std::size_t i = static_cast<std::size_t>(r) * grid.cols + c;
      grid.valid[i] = z > 0 && z <= max_depth;
      if (grid.valid[i])
        grid.points[i] =
            T_world_camera * Eigen::Vector3d((x - k.cx) * z / k.fx, (y - k.cy) * z / k.fy, z);
    }
  return grid;
}

namespace {

/// The RANSAC draws that gave a plane near enough to level with points on it, each with its
/// inlier count.
using PlaneCandidates = std::vector<std::pair<std::size_t, Plane>>;

/// Three valid points of one grid: a random one and two within o.neighbourhood cells of it.
bool drawTriple(const PointGrid& g, const FloorFitOptions& o, const std::function<int(int)>& pick,
                Eigen::Vector3d (&p)[3]) {
  const int r = pick(g.rows), c = pick(g.cols);
  bool ok = true;
  for (int j = 0; j < 3 && ok; ++j) {
    const int rr = j == 0 ? r : r + pick(2 * o.neighbourhood + 1) - o.neighbourhood;
    const int cc = j == 0 ? c : c + pick(2 * o.neighbourhood + 1) - o.neighbourhood;
    const std::size_t i = static_cast<std::size_t>(rr) * g.cols + cc;
    ok = rr >= 0 && rr < g.rows && cc >= 0 && cc < g.cols && g.valid[i];
    if (ok) p[j] = g.points[i];
  }
  return ok;
}

PlaneCandidates drawCandidates(const std::vector<PointGrid>& grids,
                               const std::vector<Eigen::Vector3d>& points,
                               const Eigen::Vector3d& up, const FloorFitOptions& o,
                               std::mt19937_64& rng) {
  const double min_cos = std::cos(o.max_tilt_deg * M_PI / 180);
  const std::function<int(int)> pick = [&rng](int n) {
    return static_cast<int>(uniformReal(rng, 0, n));
  };
  PlaneCandidates candidates;
  std::size_t tilted = 0, table_like = 0;
  for (int it = 0; it < o.iterations; ++it) {
    const PointGrid& g = grids[pick(static_cast<int>(grids.size()))];
    Eigen::Vector3d p[3];
    if (!drawTriple(g, o, pick, p)) continue;
    Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (n.norm() < 1e-4) continue;  // (nearly) collinear
    n.normalize();
    if (n.dot(up) < 0) n = -n;
    if (n.dot(up) < min_cos) {
      ++tilted;
      continue;
    }
    const Plane candidate{n, n.dot(p[0])};
    const Score s = score(candidate, points, o.inlier_distance, o.below_margin);
    if (s.below > o.max_below_fraction * points.size()) {
      ++table_like;
      continue;
    }
    if (s.inliers > 0) candidates.emplace_back(s.inliers, candidate);
  }
  if (candidates.empty()) {
    std::ostringstream msg;
    msg << "floor plane: no candidate among " << o.iterations << " RANSAC draws over "
        << points.size() << " points: " << tilted << " tilted more than " << o.max_tilt_deg
        << " deg from the up hint, " << table_like << " with more than "
        << o.max_below_fraction * 100 << " % of the points below them";
    throw std::runtime_error(msg.str());
  }
  return candidates;
}

/// The best few candidates, each refined coarse to fine (a wide band first pulls a plane that
/// three noisy points tilted by a degree or so onto the floor around it); the refined plane
/// with the most inliers wins, so the result hardly depends on the random draws.
Plane refineBest(PlaneCandidates& candidates, const std::vector<Eigen::Vector3d>& points,
                 const FloorFitOptions& o) {
  const std::size_t kept = std::min<std::size_t>(8, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + kept, candidates.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });
  Plane best;
  std::size_t most = 0;
  for (std::size_t c = 0; c < kept; ++c) {
    Plane plane = candidates[c].second;
    for (const double band : {4.0, 4.0, 2.0, 2.0, 1.0, 1.0})
      plane = refine(plane, points, band * o.inlier_distance);
    const Score s = score(plane, points, o.inlier_distance, o.below_margin);
    if (s.inliers > most && s.below <= o.max_below_fraction * points.size())
      best = plane, most = s.inliers;
  }
  if (most == 0) best = candidates.front().second;  // refining made every one table-like
  return best;
}

}  // namespace

FloorFit fitFloorPlane(const std::vector<PointGrid>& grids, const Eigen::Vector3d& up_hint,
                       const FloorFitOptions& o, std::mt19937_64& rng) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& g : grids)
    for (std::size_t i = 0; i < g.points.size(); ++i)
      if (g.valid[i]) points.push_back(g.points[i]);
  if (points.size() < 100 || grids.empty())
    throw std::runtime_error("floor plane: only " + std::to_string(points.size()) +
                             " valid depth points to fit it to");
  PlaneCandidates candidates = drawCandidates(grids, points, up_hint.normalized(), o, rng);
  FloorFit fit;
  fit.plane = refineBest(candidates, points, o);
  fit.points = points.size();
  double sum_squares = 0;
  for (const auto& p : points) {
    const double h = fit.plane.height(p);
    if (std::abs(h) <= o.inlier_distance) ++fit.inliers, sum_squares += h * h;
  }
  fit.rms = fit.inliers > 0 ? std::sqrt(sum_squares / fit.inliers) : 0;
  return fit;
}

Eigen::Isometry3d floorFrame(const Plane& plane, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& forward) {
  const Eigen::Vector3d z = plane.normal.normalized();
  Eigen::Vector3d x = forward - forward.dot(z) * z;
  if (x.norm() < 1e-6) x = z.unitOrthogonal();
  x.normalize();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear().col(0) = x;
  T.linear().col(1) = z.cross(x);
  T.linear().col(2) = z;
  T.translation() = origin - plane.height(origin) * z;
  return T;
}

}  // namespace dynslam::sim
