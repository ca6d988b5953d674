// market_crowd. Hall frame: origin at the hall's centre on the floor; rows of double-sided
// shelves run along x, aisles between them; cross aisles at both ends of the rows.
#include "dynslam/sim/Random.h"
#include "dynslam/sim/Scene.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

constexpr double kRowDepth = 0.8;    // m: two 0.4 m shelf units back to back
constexpr double kWallGap = 0.6;     // m between the outer rows and the walls
constexpr double kCrossAisle = 3.0;  // m between the rows' ends and the end walls
constexpr double kUnitWidth = 1.2;   // m (addShelfUnit)

}  // namespace

Scene buildMarketScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  const auto& w = o.world;
  const int aisles = w.aisles;
  const double hy = w.room_size_y / 2;
  const double rowLength = w.room_size_x - 2 * kCrossAisle;
  const double aisleWidth =
      aisles > 0 ? (w.room_size_y - 2 * kWallGap - (aisles + 1) * kRowDepth) / aisles : 0;
  if (aisles < 1 || aisleWidth < 1.5 || rowLength < 2 * kUnitWidth)
    throw std::invalid_argument(
        "market: " + std::to_string(aisles) + " aisles in a " + std::to_string(w.room_size_x) +
        " x " + std::to_string(w.room_size_y) +
        " m hall leave aisles narrower than 1.5 m or rows shorter than two shelf units: widen "
        "the hall (room_size_x, room_size_y) or use fewer aisles");
  Scene scene;
  addRoomShell(scene.static_mesh, textures, w.room_size_x, w.room_size_y, w.room_height, rng);
  const int wood = textures.add(makeTexture(TextureKind::Wood, rng()));
  const std::vector<int> goods = {textures.add(makeTexture(TextureKind::Posters, rng())),
                                  textures.add(makeTexture(TextureKind::Posters, rng()))};

  std::vector<double> aisleY;
  const int units = static_cast<int>(rowLength / kUnitWidth);
  for (int k = 0; k <= aisles; ++k) {
    const double y = -hy + kWallGap + kRowDepth / 2 + k * (kRowDepth + aisleWidth);
    if (k < aisles) aisleY.push_back(y + (kRowDepth + aisleWidth) / 2);
    for (int u = 0; u < units; ++u) {
      const double x = (u - (units - 1) / 2.0) * kUnitWidth;
      const int g = goods[static_cast<size_t>((k + u) % 2)];
      addShelfUnit(scene.static_mesh, placedAt(x, y + kRowDepth / 4, 0, M_PI / 2), wood, g, rng);
      addShelfUnit(scene.static_mesh, placedAt(x, y - kRowDepth / 4, 0, -M_PI / 2), wood, g, rng);
    }
  }
  const double rowEnd = units * kUnitWidth / 2, crossX = rowEnd + kCrossAisle / 2;

  // The route snakes through the aisles from one cross aisle to the other.
  for (int j = 0; j < aisles; ++j) {
    const double from = j % 2 == 0 ? -crossX : crossX;
    scene.route.push_back({from, aisleY[j]});
    scene.route.push_back({-from, aisleY[j]});
  }
  scene.orbit_centre = {0, 0};

  // People: low interaction, each paces along one aisle 0.55 m off its centre (the robot's
  // line); high, some walk from one aisle to the next through a cross aisle (meeting the robot
  // head-on and crossing its path), others pace the cross aisles.
  const auto& p = o.people;
  uint16_t id = 1;
  for (int i = 0; i < p.walkers; ++i) {
    const size_t j = static_cast<size_t>(rng() % aisles);
    const double side = i % 2 ? 0.55 : -0.55;
    const double xa = uniformReal(rng, -rowEnd + 0.5, 0), xb = uniformReal(rng, 0, rowEnd - 0.5);
    std::vector<Eigen::Vector2d> waypoints;
    if (p.interaction == "high" && i % 3 == 2) {
      const double x = (i % 2 ? 1 : -1) * (crossX + uniformReal(rng, -0.6, 0.6));
      waypoints = {{x, aisleY.front()}, {x, aisleY.back() + 0.01}};
    } else if (p.interaction == "high" && aisles > 1) {
      const size_t k = j + 1 < aisleY.size() ? j + 1 : j - 1;
      const double end = (i % 2 ? 1 : -1) * (crossX + side);
      waypoints = {{xa, aisleY[j] + side},
                   {end, aisleY[j] + side},
                   {end, aisleY[k] + side},
                   {xb, aisleY[k] + side}};
    } else {
      waypoints = {{xa, aisleY[j] + side}, {xb, aisleY[j] + side}};
    }
    const double length = FloorPath(waypoints, 1.0).length();
    scene.agents.push_back(
        makePerson(id++, FloorPath(waypoints, p.speed, uniformReal(rng, 0, 2 * length)), p.stride,
                   textures, rng));
  }
  for (int i = 0; i < p.standing; ++i) {
    const double y =
        aisleY[static_cast<size_t>(rng() % aisles)] + (i % 2 ? 1 : -1) * (aisleWidth / 2 - 0.35);
    scene.agents.push_back(
        makePerson(id++, FloorPath({{uniformReal(rng, -rowEnd + 0.5, rowEnd - 0.5), y}}, 0.0),
                   p.stride, textures, rng));
  }
  return scene;
}

}  // namespace dynslam::sim
