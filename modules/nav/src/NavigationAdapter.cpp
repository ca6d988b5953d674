#include "dynslam/nav/NavigationAdapter.h"

#include "dynslam/nav/PlanarPose.h"
#include "dynslam/nav/SweptFootprint.h"

#include <dynslam/core/CameraMount.h>
#include <dynslam/system/PoseConversion.h>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>

namespace dynslam::nav {
namespace {

using system::toIsometry;

double seconds(const mrpt::Clock::time_point& t) { return mrpt::Clock::toDouble(t); }

/// A cell of the static thinning grid: x, y cells and a height band, packed.
std::uint64_t cellKey(const Eigen::Vector3f& p, double cell, double band) {
  const auto ix = static_cast<std::int64_t>(std::floor(p.x() / cell)) & 0x1fffff;
  const auto iy = static_cast<std::int64_t>(std::floor(p.y() / cell)) & 0x1fffff;
  const auto iz = static_cast<std::int64_t>(std::floor(p.z() / band)) & 0x1fffff;
  return (static_cast<std::uint64_t>(ix) << 42) | (static_cast<std::uint64_t>(iy) << 21) |
         static_cast<std::uint64_t>(iz);
}

}  // namespace

NavigationAdapter::NavigationAdapter(const EstimateSource& source, const NavigationOptions& options)
    : source_(source), options_(options) {
  const auto& o = options_;
  T_camera_base_ = core::opticalFrameOnBody({o.camera_x, o.camera_y, o.camera_z}, o.camera_yaw_deg,
                                            o.camera_pitch_deg, o.camera_roll_deg)
                       .inverse();
}

Eigen::Isometry3d NavigationAdapter::navigationFrame(
    const system::LocalizationUpdate& first) const {
  return (toIsometry(first.pose) * T_camera_base_).inverse();
}

std::optional<Eigen::Isometry3d> NavigationAdapter::mapToNavigation() const {
  const auto first = source_.cameraPoses().first;
  if (!first) return std::nullopt;
  return navigationFrame(*first);
}

std::optional<NavigationAdapter::Robot> NavigationAdapter::robot(const CameraPoses& poses) const {
  if (!poses.first || !poses.latest) return std::nullopt;
  Robot r;
  r.T_nav_map = navigationFrame(*poses.first);
  const Eigen::Isometry3d& T_nav_map = r.T_nav_map;
  r.pose = planarOf(T_nav_map * toIsometry(poses.latest->pose) * T_camera_base_);
  r.timestamp = poses.latest->timestamp;
  r.velocity = mrpt::math::TTwist2D(0, 0, 0);
  if (poses.previous) {
    const double dt = seconds(poses.latest->timestamp) - seconds(poses.previous->timestamp);
    if (dt > 0 && dt <= options_.max_pose_gap_s) {
      const Eigen::Vector3d before =
          planarOf(T_nav_map * toIsometry(poses.previous->pose) * T_camera_base_);
      r.velocity.vx = (r.pose.x() - before.x()) / dt;
      r.velocity.vy = (r.pose.y() - before.y()) / dt;
      r.velocity.omega = mrpt::math::wrapToPi(r.pose.z() - before.z()) / dt;
    }
  }
  return r;
}

bool NavigationAdapter::getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose,
                                                mrpt::math::TTwist2D& velocity,
                                                mrpt::system::TTimeStamp& timestamp,
                                                mrpt::math::TPose2D& odometry,
                                                std::string& frame_id) const {
  if (source_.status() != system::TrackingStatus::Tracking) return false;
  const auto r = robot(source_.cameraPoses());
  if (!r) return false;
  pose = mrpt::math::TPose2D(r->pose.x(), r->pose.y(), r->pose.z());
  odometry = pose;
  velocity = r->velocity;
  timestamp = r->timestamp;
  frame_id = options_.frame_id;
  return true;
}

NavigationAdapter::StaticCache NavigationAdapter::gather(
    std::shared_ptr<const mrpt::maps::CPointsMap> map, const Eigen::Isometry3d& T_nav_map,
    const Eigen::Vector2d& robot, const NavigationOptions& o) {
  StaticCache cache;
  cache.map = map;
  cache.centre = robot;
  if (!map) return cache;
  const auto& xs = map->getPointsBufferRef_x();
  const auto& ys = map->getPointsBufferRef_y();
  const auto& zs = map->getPointsBufferRef_z();
  const Eigen::Isometry3f T = T_nav_map.cast<float>();
  const double cell = std::max(o.static_cell_m, 1e-3);
  const double band = std::max(o.footprint_height_step_m, cell);
  const float reach = static_cast<float>(o.obstacle_range_m + kStaticCacheMarginM);
  const Eigen::Vector2f centre = robot.cast<float>();
  std::unordered_set<std::uint64_t> taken;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const Eigen::Vector3f p = T * Eigen::Vector3f(xs[i], ys[i], zs[i]);
    if (!p.allFinite() || p.z() < o.floor_clearance_m || p.z() > o.max_obstacle_height_m ||
        (p.head<2>() - centre).norm() > reach)
      continue;
    if (taken.insert(cellKey(p, cell, band)).second) cache.points.push_back(p);
  }
  return cache;
}

const std::vector<Eigen::Vector3f>& NavigationAdapter::staticPoints(
    const Eigen::Isometry3d& T_nav_map, const Eigen::Vector2d& robot) const {
  using namespace std::chrono_literals;
  if (pending_.valid() && pending_.wait_for(0s) == std::future_status::ready)
    cache_ = pending_.get();
  auto map = source_.staticMap();
  const bool stale =
      !cache_ || cache_->map != map || (robot - cache_->centre).norm() > kStaticCacheMarginM;
  if (stale && (!cache_ || !options_.gather_in_background)) {
    if (pending_.valid()) pending_.wait();
    cache_ = gather(map, T_nav_map, robot, options_);
  } else if (stale && !pending_.valid()) {
    // The set in hand stays valid (it is in the navigation frame) until the new one is ready.
    pending_ = std::async(std::launch::async, &NavigationAdapter::gather, std::move(map), T_nav_map,
                          robot, options_);
  }
  return cache_->points;
}

bool NavigationAdapter::senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
                                       mrpt::system::TTimeStamp& timestamp) const {
  if (source_.status() != system::TrackingStatus::Tracking) return false;
  const auto r = robot(source_.cameraPoses());
  if (!r) return false;
  const Eigen::Isometry3d& T_nav_map = r->T_nav_map;

  // Navigation frame -> robot frame (planar; z stays the height above the floor).
  const float c = static_cast<float>(std::cos(r->pose.z())),
              s = static_cast<float>(std::sin(r->pose.z()));
  const float rx = static_cast<float>(r->pose.x()), ry = static_cast<float>(r->pose.y());
  const float range2 = static_cast<float>(options_.obstacle_range_m * options_.obstacle_range_m);
  obstacles.clear();
  const auto add = [&](const Eigen::Vector3f& p) {
    const float dx = p.x() - rx, dy = p.y() - ry;
    if (dx * dx + dy * dy > range2) return;
    obstacles.insertPointFast(c * dx + s * dy, -s * dx + c * dy, p.z());
  };
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto& points = staticPoints(T_nav_map, r->pose.head<2>());
    obstacles.reserve(points.size());
    for (const auto& p : points) add(p);
  }

  FootprintSampling sampling;
  sampling.spacing_m = options_.footprint_spacing_m;
  sampling.height_step_m = options_.footprint_height_step_m;
  sampling.bottom_m = options_.floor_clearance_m;
  sampling.max_height_m = options_.max_obstacle_height_m;
  std::vector<Eigen::Vector3f> swept;
  for (const auto& object : source_.movingObjects()) {
    const Eigen::Vector3d centre =
        T_nav_map * Eigen::Vector3d(object.pose.x, object.pose.y, object.pose.z);
    const Eigen::Vector3d v =
        T_nav_map.linear() *
        Eigen::Vector3d(object.velocity.x, object.velocity.y, object.velocity.z);
    Footprint f;
    f.centre = centre.head<2>();
    const double largest = object.category == "person" ? options_.person_max_radius_m
                                                       : options_.footprint_max_radius_m;
    f.radius = std::clamp(0.5 * std::max(object.extent.x, object.extent.z),
                          options_.footprint_min_radius_m,
                          std::max(largest, options_.footprint_min_radius_m));
    f.top = centre.z() + 0.5 * object.extent.y;
    bool moving = v.head<2>().norm() >= options_.moving_speed_m_s;
    if (object.cov) {  // the velocity block, turned into the navigation frame
      Eigen::Matrix3d cv;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) cv(r, c) = (*object.cov)(3 + r, 3 + c);
      const Eigen::Matrix2d horizontal =
          (T_nav_map.linear() * cv * T_nav_map.linear().transpose()).topLeftCorner<2, 2>();
      const double largest =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(horizontal).eigenvalues().maxCoeff();
      if (!(largest <= options_.max_velocity_sigma_m_s * options_.max_velocity_sigma_m_s))
        moving = false;
    }
    if (moving) f.velocity = v.head<2>();
    appendSweptFootprint(f, moving ? options_.obstacle_horizon_s : 0.0, sampling, swept);
  }
  for (const auto& p : swept) add(p);
  obstacles.mark_as_modified();
  timestamp = r->timestamp;
  return true;
}

}  // namespace dynslam::nav
