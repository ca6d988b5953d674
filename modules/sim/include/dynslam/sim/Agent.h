#pragma once
// The objects of a scene that have ground truth: people (walking or standing) and cars (driving
// or parked), each on a FloorPath. Scenes create them; the Simulator and the Augmenter render
// them and score what the camera sees of them.
#include <dynslam/core/Frame.h>
#include <dynslam/sim/Car.h>
#include <dynslam/sim/FloorPath.h>
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/Person.h>
#include <dynslam/sim/SimFrame.h>
#include <dynslam/sim/Texture.h>

#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace dynslam::sim {

enum class AgentKind { Person, Car };

/// "person" or "car" (the COCO class names the detectors use).
const char* categoryName(AgentKind kind);

struct Agent {
  uint16_t id = 0;  ///< instance label (>= 1)
  AgentKind kind = AgentKind::Person;
  FloorPath path{{Eigen::Vector2d::Zero()}, 0.0};
  PersonAppearance person;  ///< kind == Person
  CarAppearance car;        ///< kind == Car
  double stride = 1.4;      ///< person: m per gait cycle (two steps)
  /// person with a real appearance (SpritePeople.h): its sprite sequence (-1: rendered body)
  /// and height, m.
  int sprite_sequence = -1;
  double sprite_height_m = 0;
};

/// A person on `path` with random clothing (textures added to `textures`) and a random height
/// (scale 0.92-1.06 of 1.75 m).
Agent makePerson(uint16_t id, FloorPath path, double stride, TextureLibrary& textures,
                 std::mt19937_64& rng);
/// A car on `path` with a random paint texture and a random size around a family car.
Agent makeCar(uint16_t id, FloorPath path, TextureLibrary& textures, std::mt19937_64& rng);

/// Rigid-core pose (a person's torso, a car's body) and whether the agent moves at t.
struct AgentState {
  Eigen::Isometry3d T_world_core = Eigen::Isometry3d::Identity();
  bool moving = false;
};
AgentState agentStateAt(const Agent& agent, double t);

/// Appends the agent's triangles at time t (labelled with agent.id); none for a person with a
/// sprite (SpritePeople draws it).
void addAgentMesh(Mesh& mesh, const Agent& agent, double t);

/// Ground truth of every agent at least partly inside the image of a camera at T_world_camera,
/// given each agent's mesh at that time (`meshes[i]` belongs to `agents[i]`) and the rendered
/// label image of the whole scene: amodal box, visible pixels, visible fraction (the agent
/// rendered alone inside its box gives the unoccluded area).
std::vector<ObjectTruth> agentTruths(const std::vector<Agent>& agents,
                                     const std::vector<Mesh>& meshes, double t,
                                     const TextureLibrary& textures,
                                     const core::CameraIntrinsics& camera,
                                     const Eigen::Isometry3d& T_world_camera, const cv::Mat& label);

}  // namespace dynslam::sim
