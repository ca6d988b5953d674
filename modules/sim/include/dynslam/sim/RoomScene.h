#pragma once
// The static part of the indoor scenes: a textured room (floor, ceiling, four walls with
// posters) with shelf units along the walls, all static (instance 0). World frame: origin at
// the room's centre on the floor, z up.
#include <dynslam/sim/Mesh.h>
#include <dynslam/sim/Texture.h>

#include <random>

namespace dynslam::sim {

struct RoomLayout {
  double size_x = 5.0, size_y = 6.0, height = 2.8;  ///< m
  int shelves = 4;
};

/// Appends the room to `mesh`, adding the textures it needs to `textures`.
void buildRoom(const RoomLayout& layout, TextureLibrary& textures, Mesh& mesh,
               std::mt19937_64& rng);

}  // namespace dynslam::sim
