#include "dynslam/sim/Simulator.h"

#include "dynslam/sim/Random.h"
#include "dynslam/sim/ScenarioPaths.h"
#include "dynslam/sim/SensorNoise.h"
#include "dynslam/sim/TrajectoryPaths.h"

#include <dynslam/core/CameraMount.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

Scene buildScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  if (o.world.scene == "market") return buildMarketScene(o, textures, rng);
  if (o.world.scene == "street") return buildStreetScene(o, textures, rng);
  if (o.world.scene == "room") return buildRoomScene(o, textures, rng);
  if (o.world.scene == "corridor") return buildCorridorScene(o, textures, rng);
  throw std::invalid_argument(
      "the Simulator renders room, corridor, market and street scenes, not '" + o.world.scene +
      "'");
}

double polylineLength(const std::vector<Eigen::Vector2d>& p) {
  double length = 0;
  for (size_t i = 1; i < p.size(); ++i) length += (p[i] - p[i - 1]).norm();
  return length;
}

/// The route driven there and back as often as needed to cover `needed` metres, then cut
/// there: the robot slows to a stop at the end of the sequence, not somewhere before it.
std::vector<Eigen::Vector2d> routeOfLength(std::vector<Eigen::Vector2d> route, double needed) {
  if (route.size() < 2 || polylineLength(route) <= 0)
    throw std::invalid_argument("the scene has no route for [Camera] path = drive");
  std::vector<Eigen::Vector2d> out{route.front()};
  double length = 0;
  // Appends p; true once `needed` metres are covered (p then cut short to fit exactly).
  const auto reached = [&](const Eigen::Vector2d& p) {
    const double step = (p - out.back()).norm();
    if (length + step >= needed) {
      out.push_back(out.back() + (p - out.back()) * ((needed - length) / step));
      return true;
    }
    length += step;
    out.push_back(p);
    return false;
  };
  for (size_t i = 1;; ++i) {
    if (i == route.size()) {
      // Turn round through a point 0.7 m beside the end: two right angles instead of a
      // reversal on the spot, whose heading a spline cannot interpolate.
      const Eigen::Vector2d d = (route.back() - route[route.size() - 2]).normalized();
      if (reached(route.back() + 0.7 * Eigen::Vector2d(-d.y(), d.x()))) return out;
      std::reverse(route.begin(), route.end());
      i = 1;
    }
    if (reached(route[i])) return out;
  }
}

SplineTrajectory cameraPath(const ScenarioOptions& o, const Scene& scene) {
  const auto& c = o.camera;
  const double duration = o.world.duration;
  if (c.path == "orbit") {
    const Eigen::Vector3d centre(scene.orbit_centre.x(), scene.orbit_centre.y(), 0);
    return makeOrbit(centre, c.orbit_radius, c.height, c.orbit_period, duration,
                     centre + Eigen::Vector3d(0, 0, c.look_at_height), c.bob_amplitude,
                     c.knot_interval);
  }
  // makeDrivePath's motion lasts knot + length / speed + ramp: cover the duration, then stop.
  const double needed = std::max(1.0, c.speed * (duration - c.knot_interval));
  SplineTrajectory path = makeDrivePath(routeOfLength(scene.route, needed), c.speed, c.height,
                                        c.knot_interval, std::min(c.ramp, needed / c.speed / 2));
  if (path.endTime() < duration)
    throw std::invalid_argument("the drive path ends at " + std::to_string(path.endTime()) +
                                " s, before the duration");
  return path;
}

}  // namespace

Eigen::Isometry3d cameraInBody(const CameraMotionOptions& c) {
  return core::opticalFrameOnBody(Eigen::Vector3d(c.cam_x, c.cam_y, c.cam_z), c.cam_yaw_deg,
                                  c.cam_pitch_deg, c.cam_roll_deg);
}

core::CameraIntrinsics intrinsicsOf(const WorldOptions& w) {
  core::CameraIntrinsics k;
  k.fx = w.fx;
  k.fy = w.fy;
  k.cx = w.cx;
  k.cy = w.cy;
  k.width = w.width;
  k.height = w.height;
  return k;
}

Simulator::Simulator(ScenarioOptions options) : options_(std::move(options)) {
  const auto& w = options_.world;
  camera_ = intrinsicsOf(w);
  std::mt19937_64 sceneRng(subSeed(w.seed, kSceneStream));
  scene_ = buildScene(options_, textures_, sceneRng);
  addListedAgents(options_, scene_.agents, textures_, sceneRng);
  if (options_.people.appearance == "video") {
    sprites_ = std::make_unique<SpritePeople>(options_.people.sprites);
    std::mt19937_64 spriteRng(subSeed(w.seed, kSpriteStream));
    sprites_->dress(scene_.agents, spriteRng);
  }
  trajectory_ = std::make_unique<SplineTrajectory>(cameraPath(options_, scene_));
  T_body_camera_ = cameraInBody(options_.camera);

  std::mt19937_64 imuRng(subSeed(w.seed, kImuStream));
  imu_ = synthesizeImu(*trajectory_, 0.0, w.duration, options_.imu.imu, T_body_imu(), imuRng);
  if (options_.gnss.enabled) {
    std::mt19937_64 gnssRng(subSeed(w.seed, kGnssStream));
    gnss_ = synthesizeGnss(*trajectory_, 0.0, w.duration, options_.gnss.gnss, gnssRng);
  }
}

size_t Simulator::frameCount() const {
  return static_cast<size_t>(std::floor(options_.world.duration * options_.world.fps + 1e-9)) + 1;
}

double Simulator::frameTime(size_t index) const { return index / options_.world.fps; }

void Simulator::renderFrame(size_t index, SimFrame& out) const {
  const double t = frameTime(index);
  renderAt(t, trajectory_->sample(t).T_world_body * T_body_camera_, index, out);
  out.index = index;
}

void Simulator::renderAt(double t, const Eigen::Isometry3d& T_world_camera, size_t noise_index,
                         SimFrame& out) const {
  out.index = noise_index;
  out.t = t;
  out.T_world_camera = T_world_camera;

  Mesh mesh = scene_.static_mesh;
  std::vector<Mesh> agentMeshes(scene_.agents.size());
  for (size_t i = 0; i < scene_.agents.size(); ++i) {
    addAgentMesh(agentMeshes[i], scene_.agents[i], out.t);
    mesh.insert(mesh.end(), agentMeshes[i].begin(), agentMeshes[i].end());
  }
  RasterizerOptions raster;
  raster.threads = options_.world.render_threads;
  raster.background = {scene_.background[0], scene_.background[1], scene_.background[2]};
  render(mesh, textures_, camera_, out.T_world_camera, out.image, raster);
  std::vector<ObjectTruth> spriteTruths;
  if (sprites_)
    spriteTruths = sprites_->draw(scene_.agents, out.t, camera_, out.T_world_camera, out.image);
  out.objects = agentTruths(scene_.agents, agentMeshes, out.t, textures_, camera_,
                            out.T_world_camera, out.image.label);
  appendInIdOrder(out.objects, spriteTruths);

  std::mt19937_64 noiseRng(subSeed(options_.world.seed, kFrameStreams + noise_index));
  applyRgbdNoise(out.image, options_.noise.rgbd, noiseRng);
}

}  // namespace dynslam::sim
