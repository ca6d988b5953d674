#include "dynslam/sim/Simulator.h"

#include "dynslam/sim/Random.h"
#include "dynslam/sim/RoomScene.h"
#include "dynslam/sim/ScenarioPaths.h"
#include "dynslam/sim/SensorNoise.h"
#include "dynslam/sim/TrajectoryPaths.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace dynslam::sim {
namespace {

// Independent random streams of one run (see subSeed).
enum Stream : uint64_t { kSceneStream = 0, kImuStream = 1, kGnssStream = 2, kFrameStreams = 1000 };

/// Camera optical axes (x right, y down, z forward) in the body frame (x forward, y left, z up),
/// then the small mounting rotation and offset from the ini.
Eigen::Isometry3d cameraInBody(const CameraMotionOptions& c) {
  Eigen::Matrix3d axes;
  axes << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const double d = M_PI / 180;
  const Eigen::Matrix3d mount =
      (Eigen::AngleAxisd(c.cam_yaw_deg * d, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(c.cam_pitch_deg * d, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(c.cam_roll_deg * d, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = mount * axes;
  T.translation() = Eigen::Vector3d(c.cam_x, c.cam_y, c.cam_z);
  return T;
}

/// Bounding box of the projections of the mesh's vertices in front of the camera, clipped to
/// the image; empty when nothing projects inside.
cv::Rect amodalBox(const Mesh& mesh, const core::CameraIntrinsics& k,
                   const Eigen::Isometry3d& T_camera_world) {
  double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
  for (const auto& tri : mesh)
    for (const auto& p : tri.p) {
      const Eigen::Vector3d q = T_camera_world * p;
      if (q.z() < 0.05) continue;
      const double u = k.fx * q.x() / q.z() + k.cx, v = k.fy * q.y() / q.z() + k.cy;
      u0 = std::min(u0, u), v0 = std::min(v0, v), u1 = std::max(u1, u), v1 = std::max(v1, v);
    }
  if (u1 < u0) return {};
  const int x0 = std::max(0, static_cast<int>(std::floor(u0)));
  const int y0 = std::max(0, static_cast<int>(std::floor(v0)));
  const int x1 = std::min(k.width, static_cast<int>(std::ceil(u1)) + 1);
  const int y1 = std::min(k.height, static_cast<int>(std::ceil(v1)) + 1);
  if (x1 <= x0 || y1 <= y0) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

Simulator::Simulator(ScenarioOptions options) : options_(std::move(options)) {
  const auto& w = options_.world;
  camera_.fx = w.fx;
  camera_.fy = w.fy;
  camera_.cx = w.cx;
  camera_.cy = w.cy;
  camera_.width = w.width;
  camera_.height = w.height;

  std::mt19937_64 sceneRng(subSeed(w.seed, kSceneStream));
  buildRoom({w.room_size_x, w.room_size_y, w.room_height, w.shelves}, textures_, static_mesh_,
            sceneRng);

  // People stay inside the disc the camera circles, 0.7 m clear of the camera.
  const double region = std::max(0.8, options_.camera.orbit_radius - 0.7);
  auto paths = makePeoplePaths(options_.people, region, sceneRng);
  const int skin = textures_.add(makeTexture(TextureKind::Skin, sceneRng()));
  for (size_t i = 0; i < paths.size(); ++i) {
    PersonAppearance look;
    look.shirt_texture = textures_.add(makeTexture(TextureKind::Clothing, sceneRng()));
    look.trousers_texture = textures_.add(makeTexture(TextureKind::Clothing, sceneRng()));
    look.skin_texture = skin;
    look.scale = uniformReal(sceneRng, 0.92, 1.06);
    people_.push_back({static_cast<uint16_t>(i + 1), std::move(paths[i]), look});
  }

  const auto& c = options_.camera;
  trajectory_ = std::make_unique<SplineTrajectory>(
      makeOrbit(Eigen::Vector3d::Zero(), c.orbit_radius, c.height, c.orbit_period, w.duration,
                Eigen::Vector3d(0, 0, c.look_at_height), c.bob_amplitude, c.knot_interval));
  T_body_camera_ = cameraInBody(options_.camera);

  std::mt19937_64 imuRng(subSeed(w.seed, kImuStream));
  imu_ = synthesizeImu(*trajectory_, 0.0, w.duration, options_.imu.imu,
                       Eigen::Isometry3d::Identity(), imuRng);
  if (options_.gnss.enabled) {
    std::mt19937_64 gnssRng(subSeed(w.seed, kGnssStream));
    gnss_ = synthesizeGnss(*trajectory_, 0.0, w.duration, options_.gnss.gnss, gnssRng);
  }
}

size_t Simulator::frameCount() const {
  return static_cast<size_t>(std::floor(options_.world.duration * options_.world.fps + 1e-9)) + 1;
}

double Simulator::frameTime(size_t index) const { return index / options_.world.fps; }

Mesh Simulator::agentMesh(const Agent& agent, double t) const {
  Mesh mesh;
  addPersonMesh(mesh, personPoseAt(agent.path, t, options_.people.stride), agent.look, agent.id);
  return mesh;
}

void Simulator::renderFrame(size_t index, SimFrame& out) const {
  out.index = index;
  out.t = frameTime(index);
  out.T_world_camera = trajectory_->sample(out.t).T_world_body * T_body_camera_;
  const Eigen::Isometry3d T_camera_world = out.T_world_camera.inverse();

  Mesh mesh = static_mesh_;
  std::vector<Mesh> agents;
  for (const auto& agent : people_) {
    agents.push_back(agentMesh(agent, out.t));
    mesh.insert(mesh.end(), agents.back().begin(), agents.back().end());
  }
  render(mesh, textures_, camera_, out.T_world_camera, out.image);

  out.objects.clear();
  for (size_t i = 0; i < people_.size(); ++i) {
    const auto& agent = people_[i];
    ObjectTruth truth;
    truth.id = agent.id;
    truth.box = amodalBox(agents[i], camera_, T_camera_world);
    if (truth.box.empty()) continue;
    truth.category = "person";
    const PersonPose pose = personPoseAt(agent.path, out.t, options_.people.stride);
    truth.moving = pose.moving;
    truth.T_world_object = torsoPose(pose, agent.look);
    truth.visible_pixels = cv::countNonZero(out.image.label(truth.box) == agent.id);
    // Unoccluded area: the agent alone, rendered only inside its box (a cropped camera).
    core::CameraIntrinsics crop = camera_;
    crop.cx -= truth.box.x;
    crop.cy -= truth.box.y;
    crop.width = truth.box.width;
    crop.height = truth.box.height;
    RenderOutput alone;
    render(agents[i], textures_, crop, out.T_world_camera, alone);
    const int full = cv::countNonZero(alone.label);
    truth.visible_fraction = full > 0 ? std::min(1.0, truth.visible_pixels / double(full)) : 0.0;
    out.objects.push_back(truth);
  }

  std::mt19937_64 noiseRng(subSeed(options_.world.seed, kFrameStreams + index));
  applyRgbdNoise(out.image, options_.noise.rgbd, noiseRng);
}

}  // namespace dynslam::sim
