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

/// Where the aisles are: their centre lines (y), width, and the rows' ends along x.
struct Aisles {
  std::vector<double> y;
  double width = 0, rowEnd = 0, crossX = 0;
};

/// The rows of double-sided shelves (aisles + 1 of them) with `width` between them.
Aisles addShelfRows(Mesh& mesh, const WorldOptions& w, double width, double rowLength,
                    TextureLibrary& textures, std::mt19937_64& rng) {
  const int wood = textures.add(makeTexture(TextureKind::Wood, rng()));
  const std::vector<int> goods = {textures.add(makeTexture(TextureKind::Posters, rng())),
                                  textures.add(makeTexture(TextureKind::Posters, rng()))};
  Aisles aisles;
  aisles.width = width;
  const double hy = w.room_size_y / 2;
  const int units = static_cast<int>(rowLength / kUnitWidth);
  for (int k = 0; k <= w.aisles; ++k) {
    const double y = -hy + kWallGap + kRowDepth / 2 + k * (kRowDepth + width);
    if (k < w.aisles) aisles.y.push_back(y + (kRowDepth + width) / 2);
    for (int u = 0; u < units; ++u) {
      const double x = (u - (units - 1) / 2.0) * kUnitWidth;
      const int g = goods[static_cast<size_t>((k + u) % 2)];
      addShelfUnit(mesh, placedAt(x, y + kRowDepth / 4, 0, M_PI / 2), wood, g, rng);
      addShelfUnit(mesh, placedAt(x, y - kRowDepth / 4, 0, -M_PI / 2), wood, g, rng);
    }
  }
  aisles.rowEnd = units * kUnitWidth / 2;
  aisles.crossX = aisles.rowEnd + kCrossAisle / 2;
  return aisles;
}

/// People: low interaction, each paces along one aisle 0.55 m off its centre (the robot's
/// line); high, some walk from one aisle to the next through a cross aisle (meeting the robot
/// head-on and crossing its path), others pace the cross aisles.
void addMarketPeople(Scene& scene, const PeopleOptions& p, const Aisles& a,
                     TextureLibrary& textures, std::mt19937_64& rng) {
  const auto count = a.y.size();
  uint16_t id = 1;
  for (int i = 0; i < p.walkers; ++i) {
    const size_t j = static_cast<size_t>(rng() % count);
    const double side = i % 2 ? 0.55 : -0.55;
    const double xa = uniformReal(rng, -a.rowEnd + 0.5, 0),
                 xb = uniformReal(rng, 0, a.rowEnd - 0.5);
    std::vector<Eigen::Vector2d> waypoints;
    if (p.interaction == "high" && i % 3 == 2) {
      const double x = (i % 2 ? 1 : -1) * (a.crossX + uniformReal(rng, -0.6, 0.6));
      waypoints = {{x, a.y.front()}, {x, a.y.back() + 0.01}};
    } else if (p.interaction == "high" && count > 1) {
      const size_t k = j + 1 < count ? j + 1 : j - 1;
      const double end = (i % 2 ? 1 : -1) * (a.crossX + side);
      waypoints = {
          {xa, a.y[j] + side}, {end, a.y[j] + side}, {end, a.y[k] + side}, {xb, a.y[k] + side}};
    } else {
      waypoints = {{xa, a.y[j] + side}, {xb, a.y[j] + side}};
    }
    const double length = FloorPath(waypoints, 1.0).length();
    scene.agents.push_back(
        makePerson(id++, FloorPath(waypoints, p.speed, uniformReal(rng, 0, 2 * length)), p.stride,
                   textures, rng));
  }
  for (int i = 0; i < p.standing; ++i) {
    const double y =
        a.y[static_cast<size_t>(rng() % count)] + (i % 2 ? 1 : -1) * (a.width / 2 - 0.35);
    scene.agents.push_back(
        makePerson(id++, FloorPath({{uniformReal(rng, -a.rowEnd + 0.5, a.rowEnd - 0.5), y}}, 0.0),
                   p.stride, textures, rng));
  }
}

}  // namespace

Scene buildMarketScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  const auto& w = o.world;
  const int aisles = w.aisles;
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
  const Aisles a = addShelfRows(scene.static_mesh, w, aisleWidth, rowLength, textures, rng);

  // The route snakes through the aisles from one cross aisle to the other.
  for (int j = 0; j < aisles; ++j) {
    const double from = j % 2 == 0 ? -a.crossX : a.crossX;
    scene.route.push_back({from, a.y[j]});
    scene.route.push_back({-from, a.y[j]});
  }
  scene.orbit_centre = {0, 0};
  addMarketPeople(scene, o.people, a, textures, rng);
  return scene;
}

}  // namespace dynslam::sim
