#include "dynslam/sim/RoomScene.h"

#include "dynslam/sim/Random.h"

namespace dynslam::sim {
namespace {

Eigen::Isometry3d placed(double x, double y, double z, double yaw = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

/// A shelf unit: two side panels, four boards, and a few boxes standing on the boards.
void addShelf(Mesh& mesh, const Eigen::Isometry3d& T, int wood, int boxes,
              std::mt19937_64& rng) {
  const double w = 1.2, d = 0.4, h = 1.9;
  addBox(mesh, T * placed(0, -w / 2, h / 2), {d / 2, 0.02, h / 2}, wood, 0, 0.6);
  addBox(mesh, T * placed(0, w / 2, h / 2), {d / 2, 0.02, h / 2}, wood, 0, 0.6);
  addBox(mesh, T * placed(-d / 2, 0, h / 2), {0.01, w / 2, h / 2}, wood, 0, 0.6);  // back
  for (int level = 0; level < 4; ++level) {
    const double z = 0.1 + level * 0.55;
    addBox(mesh, T * placed(0, 0, z), {d / 2, w / 2, 0.015}, wood, 0, 0.6);
    for (double y = -w / 2 + 0.15; y < w / 2 - 0.15; y += uniformReal(rng, 0.22, 0.4)) {
      const double bh = uniformReal(rng, 0.12, 0.4), bw = uniformReal(rng, 0.06, 0.12);
      addBox(mesh, T * placed(uniformReal(rng, -0.05, 0.05), y, z + 0.015 + bh / 2, uniformReal(rng, -0.3, 0.3)),
             {0.1, bw, bh / 2}, boxes, 0, 0.4);
    }
  }
}

}  // namespace

void buildRoom(const RoomLayout& room, TextureLibrary& textures, Mesh& mesh,
               std::mt19937_64& rng) {
  const int tiles = textures.add(makeTexture(TextureKind::Tiles, rng()));
  const int ceiling = textures.add(makeTexture(TextureKind::Checker, rng()));
  const int bricks = textures.add(makeTexture(TextureKind::Bricks, rng()));
  const int posters = textures.add(makeTexture(TextureKind::Posters, rng()));
  const int wood = textures.add(makeTexture(TextureKind::Wood, rng()));
  const int boxes = textures.add(makeTexture(TextureKind::Posters, rng()));

  const double hx = room.size_x / 2, hy = room.size_y / 2, h = room.height;
  addQuad(mesh, {-hx, -hy, 0}, {room.size_x, 0, 0}, {0, room.size_y, 0}, tiles, 0, 1.0);
  addQuad(mesh, {-hx, -hy, h}, {room.size_x, 0, 0}, {0, room.size_y, 0}, ceiling, 0, 1.5);
  // Walls alternate brick and poster textures so no two neighbouring walls look alike.
  addQuad(mesh, {-hx, -hy, 0}, {room.size_x, 0, 0}, {0, 0, h}, bricks, 0, 1.2);
  addQuad(mesh, {-hx, hy, 0}, {room.size_x, 0, 0}, {0, 0, h}, posters, 0, 1.6);
  addQuad(mesh, {-hx, -hy, 0}, {0, room.size_y, 0}, {0, 0, h}, posters, 0, 1.6);
  addQuad(mesh, {hx, -hy, 0}, {0, room.size_y, 0}, {0, 0, h}, bricks, 0, 1.2);

  // Shelf units against the walls, facing the room, spread round the room.
  for (int i = 0; i < room.shelves; ++i) {
    const int wall = i % 4;
    const double along = (i / 4 % 2 == 0 ? -0.25 : 0.25) + uniformReal(rng, -0.1, 0.1);
    Eigen::Isometry3d T;
    switch (wall) {
      case 0: T = placed(along * room.size_x, -hy + 0.22, 0, M_PI / 2); break;
      case 1: T = placed(-along * room.size_x, hy - 0.22, 0, -M_PI / 2); break;
      case 2: T = placed(-hx + 0.22, along * room.size_y, 0, 0); break;
      default: T = placed(hx - 0.22, -along * room.size_y, 0, M_PI); break;
    }
    addShelf(mesh, T, wood, boxes, rng);
  }
}

}  // namespace dynslam::sim
