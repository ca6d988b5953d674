// A corridor: a long narrow room (room_size_x long, room_size_y wide) with doors and notice
// boards along both walls. Origin at its centre on the floor, x along it.
#include "dynslam/sim/Random.h"
#include "dynslam/sim/Scene.h"

#include <stdexcept>
#include <string>

namespace dynslam::sim {

Scene buildCorridorScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  const auto& w = o.world;
  const double hx = w.room_size_x / 2, hy = w.room_size_y / 2;
  if (w.room_size_x < 6 || w.room_size_y < 1.8)
    throw std::invalid_argument(
        "corridor: room_size_x >= 6 m and room_size_y >= 1.8 m are "
        "needed for people to pass the robot, got " +
        std::to_string(w.room_size_x) + " x " + std::to_string(w.room_size_y));
  Scene scene;
  addRoomShell(scene.static_mesh, textures, w.room_size_x, w.room_size_y, w.room_height, rng);
  const int wood = textures.add(makeTexture(TextureKind::Wood, rng()));
  const int notices = textures.add(makeTexture(TextureKind::Posters, rng()));
  // Doors (standing 3 cm out of the wall) every 4-6 m, a notice board beside each.
  for (const double side : {-1.0, 1.0})
    for (double x = -hx + uniformReal(rng, 1, 3); x < hx - 1; x += uniformReal(rng, 4, 6)) {
      addBox(scene.static_mesh, placedAt(x, side * (hy - 0.015), 1.05), {0.45, 0.015, 1.05}, wood,
             0, 1.0);
      addBox(scene.static_mesh, placedAt(x + 1.3, side * (hy - 0.01), 1.5), {0.5, 0.01, 0.35},
             notices, 0, 1.0);
    }
  scene.route = {{-hx + 1, 0}, {hx - 1, 0}};

  // People pace along the corridor: low interaction near the walls, high interaction on lanes
  // 0.45 m beside the robot's line (passing it head-on) or across from door to door.
  const auto& p = o.people;
  uint16_t id = 1;
  for (int i = 0; i < p.walkers; ++i) {
    const double side = i % 2 ? 1.0 : -1.0;
    const double x = uniformReal(rng, -hx + 1, hx - 1);
    std::vector<Eigen::Vector2d> waypoints;
    if (p.interaction == "high" && i % 3 == 2) {
      waypoints = {{x, -hy + 0.3}, {x + uniformReal(rng, -0.5, 0.5), hy - 0.3}};
    } else {
      const double lane = side * (p.interaction == "high" ? 0.45 : hy - 0.45);
      waypoints = {{-hx + 0.8, lane}, {hx - 0.8, lane}};
    }
    const double length = FloorPath(waypoints, 1.0).length();
    scene.agents.push_back(
        makePerson(id++, FloorPath(waypoints, p.speed, uniformReal(rng, 0, 2 * length)), p.stride,
                   textures, rng));
  }
  for (int i = 0; i < p.standing; ++i)
    scene.agents.push_back(makePerson(
        id++, FloorPath({{uniformReal(rng, -hx + 1, hx - 1), (i % 2 ? 1 : -1) * (hy - 0.35)}}, 0.0),
        p.stride, textures, rng));
  return scene;
}

}  // namespace dynslam::sim
