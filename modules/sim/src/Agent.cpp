#include "dynslam/sim/Agent.h"

#include "dynslam/sim/Random.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace dynslam::sim {
namespace {

Eigen::Isometry3d groundPose(const FloorPath& path, double t) {
  Eigen::Vector2d xy;
  double heading = 0;
  path.at(t, xy, heading);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(xy.x(), xy.y(), 0);
  T.linear() = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
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

const char* categoryName(AgentKind kind) { return kind == AgentKind::Car ? "car" : "person"; }

Agent makePerson(uint16_t id, FloorPath path, double stride, TextureLibrary& textures,
                 std::mt19937_64& rng) {
  Agent a;
  a.id = id;
  a.kind = AgentKind::Person;
  a.path = std::move(path);
  a.stride = stride;
  a.person.shirt_texture = textures.add(makeTexture(TextureKind::Clothing, rng()));
  a.person.trousers_texture = textures.add(makeTexture(TextureKind::Clothing, rng()));
  a.person.skin_texture = textures.add(makeTexture(TextureKind::Skin, rng()));
  a.person.scale = uniformReal(rng, 0.92, 1.06);
  return a;
}

Agent makeCar(uint16_t id, FloorPath path, TextureLibrary& textures, std::mt19937_64& rng) {
  Agent a;
  a.id = id;
  a.kind = AgentKind::Car;
  a.path = std::move(path);
  a.car.paint_texture = textures.add(makeTexture(TextureKind::CarPaint, rng()));
  a.car.tyre_texture = textures.add(makeTexture(TextureKind::Asphalt, rng(), 64));
  a.car.length = uniformReal(rng, 4.0, 4.8);
  a.car.width = uniformReal(rng, 1.7, 1.9);
  a.car.height = uniformReal(rng, 1.4, 1.6);
  return a;
}

AgentState agentStateAt(const Agent& agent, double t) {
  AgentState s;
  if (agent.kind == AgentKind::Car) {
    s.T_world_core = carBodyPose(groundPose(agent.path, t), agent.car);
    s.moving = !agent.path.standing();
  } else {
    const PersonPose pose = personPoseAt(agent.path, t, agent.stride);
    s.T_world_core = torsoPose(pose, agent.person);
    s.moving = pose.moving;
  }
  return s;
}

void addAgentMesh(Mesh& mesh, const Agent& agent, double t) {
  if (agent.sprite_sequence >= 0) return;
  if (agent.kind == AgentKind::Car)
    addCarMesh(mesh, groundPose(agent.path, t), agent.car, agent.id);
  else
    addPersonMesh(mesh, personPoseAt(agent.path, t, agent.stride), agent.person, agent.id);
}

std::vector<ObjectTruth> agentTruths(const std::vector<Agent>& agents,
                                     const std::vector<Mesh>& meshes, double t,
                                     const TextureLibrary& textures,
                                     const core::CameraIntrinsics& camera,
                                     const Eigen::Isometry3d& T_world_camera,
                                     const cv::Mat& label) {
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  std::vector<ObjectTruth> truths;
  for (size_t i = 0; i < agents.size(); ++i) {
    ObjectTruth truth;
    truth.id = agents[i].id;
    truth.box = amodalBox(meshes[i], camera, T_camera_world);
    if (truth.box.empty()) continue;
    truth.category = categoryName(agents[i].kind);
    const AgentState state = agentStateAt(agents[i], t);
    truth.moving = state.moving;
    truth.T_world_object = state.T_world_core;
    truth.visible_pixels = cv::countNonZero(label(truth.box) == truth.id);
    // Unoccluded area: the agent alone, rendered only inside its box (a cropped camera).
    core::CameraIntrinsics crop = camera;
    crop.cx -= truth.box.x;
    crop.cy -= truth.box.y;
    crop.width = truth.box.width;
    crop.height = truth.box.height;
    RenderOutput alone;
    render(meshes[i], textures, crop, T_world_camera, alone);
    const int full = cv::countNonZero(alone.label);
    truth.visible_fraction = full > 0 ? std::min(1.0, truth.visible_pixels / double(full)) : 0.0;
    truths.push_back(truth);
  }
  return truths;
}

}  // namespace dynslam::sim
