#include "dynslam/sim/Augmenter.h"

#include "dynslam/sim/Compositor.h"
#include "dynslam/sim/FloorMap.h"
#include "dynslam/sim/FloorPlanner.h"
#include "dynslam/sim/Random.h"
#include "dynslam/sim/RealRgbdStream.h"
#include "dynslam/sim/Simulator.h"

#include <dynslam/core/TrajectoryFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::sim {
namespace {

// sevenscenes2rawlog writes the same stamp to the observation and to the ground truth; MRPT's
// clock keeps 100 ns ticks, so 1 ms is loose enough for rounding and far below a frame period.
constexpr double kStampTolerance = 1e-3;

std::string groundTruthPath(const AugmentOptions& a) {
  if (!a.groundtruth.empty()) return a.groundtruth;
  const fs::path rawlog(a.rawlog);
  return (rawlog.parent_path() / (rawlog.stem().string() + ".gt.tum")).string();
}

}  // namespace

Augmenter::~Augmenter() = default;

Augmenter::Augmenter(const ScenarioOptions& options) : options_(options) {
  const AugmentOptions& a = options_.augment;
  a.validate();
  rawlog_path_ = a.rawlog;
  readRealFrames();
  start_time_ = frames_.front().stamp;

  // The depth of frames spread over the sequence: the floor, the free floor, what is seen.
  const std::size_t count = std::clamp<std::size_t>(a.floor_frames, 1, frames_.size());
  std::vector<std::size_t> sampled;
  for (std::size_t j = 0; j < count; ++j)
    sampled.push_back(count == 1 ? 0 : j * (frames_.size() - 1) / (count - 1));
  sampled.erase(std::unique(sampled.begin(), sampled.end()), sampled.end());
  std::vector<cv::Mat> depths;
  std::vector<PointGrid> grids;
  {
    RealRgbdStream stream(rawlog_path_);
    for (std::size_t i : sampled) {
      const core::Frame& f = stream.frame(frames_[i].rgbd_number);
      if (depths.empty()) camera_ = f.intrinsics;
      depths.push_back(f.depth.clone());
      grids.push_back(backProject(f.depth, f.intrinsics, frames_[i].T_world_camera,
                                  std::max(1, a.floor_pixel_step), a.floor_max_depth));
    }
  }
  std::mt19937_64 scene_rng(subSeed(options_.world.seed, kSceneStream));
  findFloorAndPlaceAgents(grids, depths, sampled, scene_rng);
  synthesizeInertialSensors();
}

void Augmenter::readRealFrames() {
  const AugmentOptions& a = options_.augment;
  if (!fs::is_regular_file(rawlog_path_))
    throw std::runtime_error("[Augment] rawlog '" + rawlog_path_ + "' does not exist");
  const std::string gt_path = groundTruthPath(a);
  if (!fs::is_regular_file(gt_path))
    throw std::runtime_error("[Augment] ground truth '" + gt_path + "' does not exist" +
                             (a.groundtruth.empty() ? " (derived from the rawlog's name)" : ""));
  core::Trajectory gt = core::readTum(gt_path);
  std::stable_sort(gt.begin(), gt.end(), [](auto& p, auto& q) { return p.t < q.t; });

  const std::vector<double> stamps = RealRgbdStream::rgbdStamps(rawlog_path_);
  for (std::size_t n = 0; n < stamps.size(); ++n) {
    const core::StampedPose* pose = core::poseNear(gt, stamps[n], kStampTolerance);
    if (!pose) {
      ++summary_.frames_without_pose;
      continue;
    }
    if (!frames_.empty() && stamps[n] <= frames_.back().stamp)
      throw std::runtime_error("rawlog '" + rawlog_path_ + "': RGB-D stamps do not increase at " +
                               "observation " + std::to_string(n));
    frames_.push_back({n, stamps[n], pose->T_world_body});
  }
  if (frames_.size() < 2)
    throw std::runtime_error("rawlog '" + rawlog_path_ + "' has " + std::to_string(frames_.size()) +
                             " RGB-D frames with a pose in '" + gt_path +
                             "' (stamps within 1 ms; " + std::to_string(stamps.size()) +
                             " RGB-D observations): need 2 or more");
}

void Augmenter::synthesizeInertialSensors() {
  // IMU: a spline through the body poses (camera poses * T_camera_body) in F.
  T_body_camera_ = cameraInBody(options_.camera);
  const Eigen::Isometry3d T_camera_body = T_body_camera_.inverse();
  core::Trajectory body, cameras;  // in F, t since the first frame
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    const Eigen::Isometry3d T_floor_cam = T_floor_camera(i);
    cameras.push_back({frameTime(i), T_floor_cam});
    body.push_back({frameTime(i), T_floor_cam * T_camera_body});
  }
  trajectory_ =
      std::make_unique<SplineTrajectory>(fitSplineToPoses(body, options_.augment.knot_interval));
  summary_.spline_error = splineFitError(*trajectory_, cameras, T_body_camera_);
  const double end = frameTime(frames_.size() - 1);
  std::mt19937_64 imu_rng(subSeed(options_.world.seed, kImuStream));
  imu_ = synthesizeImu(*trajectory_, 0.0, end, options_.imu.imu, T_body_imu(), imu_rng);
  if (options_.gnss.enabled) {
    std::mt19937_64 gnss_rng(subSeed(options_.world.seed, kGnssStream));
    gnss_ = synthesizeGnss(*trajectory_, 0.0, end, options_.gnss.gnss, gnss_rng);
  }
}

void Augmenter::findFloorAndPlaceAgents(const std::vector<PointGrid>& grids,
                                        const std::vector<cv::Mat>& depths,
                                        const std::vector<std::size_t>& sampled,
                                        std::mt19937_64& rng) {
  const AugmentOptions& a = options_.augment;
  Eigen::Vector3d down = Eigen::Vector3d::Zero(), ahead = Eigen::Vector3d::Zero(),
                  centre = Eigen::Vector3d::Zero();
  for (const auto& f : frames_) {
    down += f.T_world_camera.linear().col(1);
    ahead += f.T_world_camera.linear().col(2);
    centre += f.T_world_camera.translation();
  }
  FloorFitOptions fit_options;
  fit_options.inlier_distance = a.floor_inlier_distance;
  fit_options.iterations = a.floor_ransac_iterations;
  fit_options.max_tilt_deg = a.floor_max_tilt_deg;
  std::mt19937_64 floor_rng(subSeed(options_.world.seed, kFloorStream));
  summary_.floor = fitFloorPlane(grids, -down, fit_options, floor_rng);

  // A first floor frame under the cameras' mean position, x along their mean view; the map is
  // built in it, then F moves its origin to the region centre.
  const Eigen::Isometry3d T_world_map =
      floorFrame(summary_.floor.plane, centre / frames_.size(), ahead);
  CameraTrack track;
  const FloorMap map = buildFloorMap(grids, depths, sampled, T_world_map.inverse(), track);
  const Eigen::Vector2d region = chooseRegionCentre(map, std::min(1.0, a.region_radius));
  Eigen::Isometry3d T_world_floor = T_world_map;
  T_world_floor.translation() += T_world_map.linear() * Eigen::Vector3d(region.x(), region.y(), 0);
  T_floor_world_ = T_world_floor.inverse();
  summary_.T_world_floor = T_world_floor;
  summariseClearFloor(map);
  placeAgents(map, region, track, rng);
}

FloorMap Augmenter::buildFloorMap(const std::vector<PointGrid>& grids,
                                  const std::vector<cv::Mat>& depths,
                                  const std::vector<std::size_t>& sampled,
                                  const Eigen::Isometry3d& T_map_world, CameraTrack& track) const {
  const AugmentOptions& a = options_.augment;
  FloorMapOptions map_options;
  map_options.cell = a.map_cell;
  map_options.obstacle_height = a.obstacle_height;
  map_options.clearance = a.clearance;
  map_options.floor_band = std::max(0.03, 2.5 * a.floor_inlier_distance);
  std::vector<PointGrid> in_map = grids;
  Eigen::Vector2d lo(-1, -1), hi(1, 1);  // the cameras' surroundings at least
  for (auto& g : in_map)
    for (std::size_t i = 0; i < g.points.size(); ++i)
      if (g.valid[i]) {
        g.points[i] = T_map_world * g.points[i];
        if (std::abs(g.points[i].z()) <= map_options.floor_band)
          lo = lo.cwiseMin(g.points[i].head<2>()), hi = hi.cwiseMax(g.points[i].head<2>());
      }
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    track.t.push_back(frameTime(i));
    track.xy.push_back((T_map_world * frames_[i].T_world_camera.translation()).head<2>());
    lo = lo.cwiseMin(track.xy.back()), hi = hi.cwiseMax(track.xy.back());
  }
  FloorMap map(lo - Eigen::Vector2d(0.5, 0.5), hi + Eigen::Vector2d(0.5, 0.5), map_options);
  for (const auto& g : in_map) map.addPoints(g);
  for (std::size_t j = 0; j < depths.size(); ++j)
    map.addView(depths[j], camera_, T_map_world * frames_[sampled[j]].T_world_camera,
                a.camera_clearance + 0.5);
  map.finish();
  return map;
}

void Augmenter::summariseClearFloor(const FloorMap& map) {
  Eigen::Vector2d clear_lo(1e9, 1e9), clear_hi(-1e9, -1e9);
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c)
      if (map.clear().at<uint8_t>(r, c)) {
        ++summary_.clear_cells;
        clear_lo = clear_lo.cwiseMin(map.cellCentre(r, c));
        clear_hi = clear_hi.cwiseMax(map.cellCentre(r, c));
      }
  summary_.region_extent_m =
      (clear_hi - clear_lo).cwiseMax(0.0) + Eigen::Vector2d::Constant(options_.augment.map_cell);
}

void Augmenter::placeAgents(const FloorMap& map, const Eigen::Vector2d& region,
                            const CameraTrack& track, std::mt19937_64& rng) {
  const AugmentOptions& a = options_.augment;
  FloorPlanOptions plan;
  plan.region_radius = a.region_radius;
  plan.min_walk_length = a.min_walk_length;
  plan.camera_clearance = a.camera_clearance;
  const auto people =
      planPeople(options_.people, map, region, track, plan, rng, &summary_.fallbacks);
  const auto cars = planCars(options_.cars, map, region, track, plan, rng);
  uint16_t id = 1;
  for (const auto& path : people)
    agents_.push_back(makePerson(id++, path, options_.people.stride, textures_, rng));
  for (const auto& path : cars) agents_.push_back(makeCar(id++, path, textures_, rng));
  if (options_.people.appearance == "video") {
    sprites_ = std::make_unique<SpritePeople>(options_.people.sprites);
    std::mt19937_64 spriteRng(subSeed(options_.world.seed, kSpriteStream));
    sprites_->dress(agents_, spriteRng);
  }

  summary_.min_agent_separation = summary_.min_camera_distance =
      std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector2d> at(agents_.size());
  for (std::size_t k = 0; k < track.t.size(); ++k) {
    for (std::size_t i = 0; i < agents_.size(); ++i) {
      double heading;
      agents_[i].path.at(track.t[k], at[i], heading);
      summary_.min_camera_distance =
          std::min(summary_.min_camera_distance, (at[i] + region - track.xy[k]).norm());
      for (std::size_t j = 0; j < i; ++j)
        summary_.min_agent_separation =
            std::min(summary_.min_agent_separation, (at[i] - at[j]).norm());
    }
  }
}

double Augmenter::frameTime(size_t index) const { return frames_.at(index).stamp - start_time_; }

Eigen::Isometry3d Augmenter::T_floor_camera(size_t index) const {
  return T_floor_world_ * frames_.at(index).T_world_camera;
}

void Augmenter::renderFrame(size_t index, SimFrame& out) const {
  out.index = index;
  out.t = frameTime(index);
  out.T_world_camera = T_floor_camera(index);

  std::vector<Mesh> meshes(agents_.size());
  Mesh all;
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    addAgentMesh(meshes[i], agents_[i], out.t);
    all.insert(all.end(), meshes[i].begin(), meshes[i].end());
  }
  RenderOutput movers;
  render(all, textures_, camera_, out.T_world_camera, movers);

  cv::Mat inserted;
  {
    const std::lock_guard<std::mutex> lock(stream_mutex_);
    if (!stream_) stream_ = std::make_unique<RealRgbdStream>(rawlog_path_);
    const core::Frame& real = stream_->frame(frames_[index].rgbd_number);
    if (real.rgb.empty() || real.depth.size() != real.rgb.size() ||
        real.rgb.cols != camera_.width || real.rgb.rows != camera_.height)
      throw std::runtime_error("rawlog '" + rawlog_path_ + "': RGB-D observation " +
                               std::to_string(frames_[index].rgbd_number) +
                               " lacks colour or differs in size from the first frame");
    inserted = compositeOverReal(movers, real.rgb, real.depth, out.image);
  }
  std::vector<ObjectTruth> spriteTruths;
  if (sprites_) {
    spriteTruths = sprites_->draw(agents_, out.t, camera_, out.T_world_camera, out.image);
    inserted = out.image.label != 0;  // the sprites' pixels get the noise too
  }
  std::mt19937_64 noise_rng(subSeed(options_.world.seed, kFrameStreams + index));
  applyRgbdNoiseMasked(out.image, inserted, options_.noise.rgbd, noise_rng);
  out.objects =
      agentTruths(agents_, meshes, out.t, textures_, camera_, out.T_world_camera, out.image.label);
  appendInIdOrder(out.objects, spriteTruths);
}

}  // namespace dynslam::sim
