#pragma once
// A scenario's world before any frame is rendered: the static geometry, the agents (people and
// cars with ground truth) and the route a ground robot takes. One builder per kind of scene;
// the Simulator picks one by [Scenario] scene and moves the camera along an orbit or the route.
// World frame of every scene: z up, the floor at z = 0.
#include <dynslam/sim/Agent.h>
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/ScenarioOptions.h>
#include <dynslam/sim/Texture.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace dynslam::sim {

struct Scene {
  Mesh static_mesh;           ///< instance 0
  std::vector<Agent> agents;  ///< ids 1, 2, ... (people first, then cars)
  /// Floor waypoints of the robot's route ([Camera] path = drive).
  std::vector<Eigen::Vector2d> route;
  /// Centre of a handheld orbit ([Camera] path = orbit), on the floor.
  Eigen::Vector2d orbit_centre = Eigen::Vector2d::Zero();
  /// Colour where no geometry is hit (BGR): the sky outdoors; indoors every ray hits a wall.
  std::array<uint8_t, 3> background{40, 40, 40};
};

/// The room of indoor_people: walls, posters and shelf units; people inside the disc the
/// orbiting camera circles (high interaction: crossing lines; low: parallel lanes); the route
/// runs round the room 1.3 m from the walls.
Scene buildRoomScene(const ScenarioOptions& options, TextureLibrary& textures,
                     std::mt19937_64& rng);

/// A corridor (room_size_x long, room_size_y wide) with doors and notice boards; the route
/// runs along its centre line; people pace along it beside the walls (low interaction) or on
/// lanes beside the robot's line and across from door to door (high).
Scene buildCorridorScene(const ScenarioOptions& options, TextureLibrary& textures,
                         std::mt19937_64& rng);

/// market_crowd: a hall with rows of double-sided shelves and aisles between them; the route
/// snakes through the aisles; people walk along aisles (low interaction) or from aisle to aisle
/// through the cross aisles (high), others stand at the shelves.
Scene buildMarketScene(const ScenarioOptions& options, TextureLibrary& textures,
                       std::mt19937_64& rng);

/// outdoor_street: a road with two lanes and parking strips between sidewalks and building
/// rows, street furniture; cars drive round the block (out on one lane, back on the other) or
/// stand parked; people walk along the sidewalks (low) or also across them and head-on past the
/// robot (high); the route runs out along the right sidewalk and back.
Scene buildStreetScene(const ScenarioOptions& options, TextureLibrary& textures,
                       std::mt19937_64& rng);

/// The shell of a room or hall: floor, ceiling and four walls (brick and poster textures).
void addRoomShell(Mesh& mesh, TextureLibrary& textures, double size_x, double size_y, double height,
                  std::mt19937_64& rng);

/// A shelf unit (1.2 m wide, 0.4 m deep, 1.9 m high) with boxes on its boards, its open side
/// facing +x of T_world_shelf (origin on the floor at the unit's centre).
void addShelfUnit(Mesh& mesh, const Eigen::Isometry3d& T_world_shelf, int wood, int goods,
                  std::mt19937_64& rng);

/// T_world = translation (x, y, z) and rotation yaw about z.
Eigen::Isometry3d placedAt(double x, double y, double z, double yaw = 0.0);

}  // namespace dynslam::sim
