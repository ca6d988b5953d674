#include "dynslam/sim/Random.h"
#include "dynslam/sim/ScenarioPaths.h"
#include "dynslam/sim/Scene.h"

#include <algorithm>

namespace dynslam::sim {

Eigen::Isometry3d placedAt(double x, double y, double z, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

void addShelfUnit(Mesh& mesh, const Eigen::Isometry3d& T, int wood, int goods,
                  std::mt19937_64& rng) {
  const double w = 1.2, d = 0.4, h = 1.9;
  addBox(mesh, T * placedAt(0, -w / 2, h / 2), {d / 2, 0.02, h / 2}, wood, 0, 0.6);
  addBox(mesh, T * placedAt(0, w / 2, h / 2), {d / 2, 0.02, h / 2}, wood, 0, 0.6);
  addBox(mesh, T * placedAt(-d / 2, 0, h / 2), {0.01, w / 2, h / 2}, wood, 0, 0.6);  // back
  for (int level = 0; level < 4; ++level) {
    const double z = 0.1 + level * 0.55;
    addBox(mesh, T * placedAt(0, 0, z), {d / 2, w / 2, 0.015}, wood, 0, 0.6);
    for (double y = -w / 2 + 0.15; y < w / 2 - 0.15; y += uniformReal(rng, 0.22, 0.4)) {
      const double bh = uniformReal(rng, 0.12, 0.4), bw = uniformReal(rng, 0.06, 0.12);
      addBox(mesh,
             T * placedAt(uniformReal(rng, -0.05, 0.05), y, z + 0.015 + bh / 2,
                          uniformReal(rng, -0.3, 0.3)),
             {0.1, bw, bh / 2}, goods, 0, 0.4);
    }
  }
}

void addRoomShell(Mesh& mesh, TextureLibrary& textures, double size_x, double size_y, double h,
                  std::mt19937_64& rng) {
  const int tiles = textures.add(makeTexture(TextureKind::Tiles, rng()));
  const int ceiling = textures.add(makeTexture(TextureKind::Checker, rng()));
  const int bricks = textures.add(makeTexture(TextureKind::Bricks, rng()));
  const int posters = textures.add(makeTexture(TextureKind::Posters, rng()));
  const double hx = size_x / 2, hy = size_y / 2;
  addQuad(mesh, {-hx, -hy, 0}, {size_x, 0, 0}, {0, size_y, 0}, tiles, 0, 1.0);
  addQuad(mesh, {-hx, -hy, h}, {size_x, 0, 0}, {0, size_y, 0}, ceiling, 0, 1.5);
  // Walls alternate brick and poster textures so no two neighbouring walls look alike.
  addQuad(mesh, {-hx, -hy, 0}, {size_x, 0, 0}, {0, 0, h}, bricks, 0, 1.2);
  addQuad(mesh, {-hx, hy, 0}, {size_x, 0, 0}, {0, 0, h}, posters, 0, 1.6);
  addQuad(mesh, {-hx, -hy, 0}, {0, size_y, 0}, {0, 0, h}, posters, 0, 1.6);
  addQuad(mesh, {hx, -hy, 0}, {0, size_y, 0}, {0, 0, h}, bricks, 0, 1.2);
}

Scene buildRoomScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  const auto& w = o.world;
  Scene scene;
  addRoomShell(scene.static_mesh, textures, w.room_size_x, w.room_size_y, w.room_height, rng);
  const int wood = textures.add(makeTexture(TextureKind::Wood, rng()));
  const int goods = textures.add(makeTexture(TextureKind::Posters, rng()));
  // Shelf units against the walls, facing the room, spread round the room.
  const double hx = w.room_size_x / 2, hy = w.room_size_y / 2;
  for (int i = 0; i < w.shelves; ++i) {
    const double along = (i / 4 % 2 == 0 ? -0.25 : 0.25) + uniformReal(rng, -0.1, 0.1);
    Eigen::Isometry3d T;
    switch (i % 4) {
      case 0:
        T = placedAt(along * w.room_size_x, -hy + 0.22, 0, M_PI / 2);
        break;
      case 1:
        T = placedAt(-along * w.room_size_x, hy - 0.22, 0, -M_PI / 2);
        break;
      case 2:
        T = placedAt(-hx + 0.22, along * w.room_size_y, 0, 0);
        break;
      default:
        T = placedAt(hx - 0.22, -along * w.room_size_y, 0, M_PI);
        break;
    }
    addShelfUnit(scene.static_mesh, T, wood, goods, rng);
  }

  // People stay inside the disc the camera circles, 0.7 m clear of the camera.
  const double region = std::max(0.8, o.camera.orbit_radius - 0.7);
  auto paths = makePeoplePaths(o.people, region, rng);
  for (size_t i = 0; i < paths.size(); ++i)
    scene.agents.push_back(makePerson(static_cast<uint16_t>(i + 1), std::move(paths[i]),
                                      o.people.stride, textures, rng));

  const double ix = std::max(0.3, hx - 1.3), iy = std::max(0.3, hy - 1.3);
  scene.route = {{-ix, -iy}, {ix, -iy}, {ix, iy}, {-ix, iy}, {-ix, -iy}};
  return scene;
}

}  // namespace dynslam::sim
