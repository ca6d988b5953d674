// outdoor_street. Street frame: x along the street (the route runs over [5, L - 5]), y across
// it (the road |y| <= R/2, sidewalks R/2 <= |y| <= R/2 + S, facades behind them), z up.
#include "dynslam/sim/Random.h"
#include "dynslam/sim/Scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::sim {
namespace {

constexpr double kBeyondEnds = 60.0;  // m of street past both ends of the route's stretch

/// Building rows on one side (side = +1 left, -1 right), each building a box with a shop front.
void addBuildingRow(Mesh& mesh, double side, double facade_y, double x0, double x1,
                    const std::vector<int>& facades, int shopfront, std::mt19937_64& rng) {
  for (double x = x0; x < x1;) {
    const double width = std::min(uniformReal(rng, 8, 18), x1 - x);
    const double height = uniformReal(rng, 6, 18), depth = 8.0;
    const int texture = facades[static_cast<size_t>(rng() % facades.size())];
    addBox(mesh, placedAt(x + width / 2, side * (facade_y + depth / 2), height / 2),
           {width / 2, depth / 2, height / 2}, texture, 0, uniformReal(rng, 1.5, 3.0));
    if (width > 4) {  // shop front: a shallow box standing out of the ground floor
      addBox(mesh, placedAt(x + width / 2, side * (facade_y - 0.15), 1.6),
             {width / 2 - 1.0, 0.15, 1.4}, shopfront, 0, 2.0);
    }
    x += width;
  }
}

/// Lamp posts and bins along one kerb (side = +1 left, -1 right).
void addStreetFurniture(Mesh& mesh, double side, double kerb_y, double length, int metal, int bins,
                        std::mt19937_64& rng) {
  for (double x = uniformReal(rng, 0, 10); x < length; x += uniformReal(rng, 15, 25)) {
    addBox(mesh, placedAt(x, side * (kerb_y + 0.4), 2.5), {0.07, 0.07, 2.5}, metal, 0, 0.5);
    addBox(mesh, placedAt(x + 0.6 * side, side * (kerb_y + 0.4), 5.0), {0.6, 0.08, 0.06}, metal, 0,
           0.5);
    const double bx = x + uniformReal(rng, 4, 8);
    addBox(mesh, placedAt(bx, side * (kerb_y + 0.5), 0.45), {0.25, 0.25, 0.45}, bins, 0, 0.5);
  }
}

/// The street's layout across it: road half-width, the facades' distance from the axis and the
/// robot's two lanes on the right sidewalk (out at y_out, back 0.8 m nearer the road).
struct StreetLayout {
  double L, R, S, facade, yOut, yBack;
  explicit StreetLayout(const WorldOptions& w)
      : L(w.street_length),
        R(w.road_width),
        S(w.sidewalk_width),
        facade(R / 2 + S),
        yOut(-(R / 2 + S / 2) - 0.4),
        yBack(yOut + 0.8) {}
};

/// Road, sidewalks, kerbs, building rows, street furniture and the buildings closing both ends.
void addStreetStatics(Mesh& m, const StreetLayout& s, TextureLibrary& textures,
                      std::mt19937_64& rng) {
  const double L = s.L, R = s.R, S = s.S, facade = s.facade;
  const int asphalt = textures.add(makeTexture(TextureKind::Asphalt, rng()));
  const int paving = textures.add(makeTexture(TextureKind::Tiles, rng()));
  const int kerb = textures.add(makeTexture(TextureKind::Checker, rng(), 64));
  const std::vector<int> facades = {textures.add(makeTexture(TextureKind::Bricks, rng())),
                                    textures.add(makeTexture(TextureKind::Bricks, rng())),
                                    textures.add(makeTexture(TextureKind::Posters, rng()))};
  const int shopfront = textures.add(makeTexture(TextureKind::Posters, rng()));
  const int metal = textures.add(makeTexture(TextureKind::Asphalt, rng(), 64));
  const int bins = textures.add(makeTexture(TextureKind::Wood, rng(), 64));

  const double x0 = -kBeyondEnds, x1 = L + kBeyondEnds;
  addQuad(m, {x0, -R / 2, 0}, {x1 - x0, 0, 0}, {0, R, 0}, asphalt, 0, 3.5);
  for (const double side : {-1.0, 1.0}) {
    addQuad(m, {x0, side * R / 2, 0}, {x1 - x0, 0, 0}, {0, side * S, 0}, paving, 0, 1.0);
    addBox(m, placedAt((x0 + x1) / 2, side * R / 2, 0.06), {(x1 - x0) / 2, 0.08, 0.06}, kerb, 0,
           0.5);
    addBuildingRow(m, side, facade, x0, x1, facades, shopfront, rng);
    addStreetFurniture(m, side, R / 2, L, metal, bins, rng);
  }
  for (const double x : {x0, x1})  // the street ends in a building across it
    addBox(m, placedAt(x + (x < 0 ? -4 : 4), 0, 7.5), {4, facade + 8, 7.5}, facades[0], 0, 2.5);
}

/// People: sidewalk lanes 0.9 m either side of the robot's lanes; in high interaction half of
/// the walkers pace across the robot's sidewalk (between the shops and the kerb) instead.
void addStreetPeople(Scene& scene, const PeopleOptions& p, const StreetLayout& s, uint16_t& id,
                     TextureLibrary& textures, std::mt19937_64& rng) {
  const double L = s.L, R = s.R, facade = s.facade;
  const std::vector<double> lanes = {s.yOut - 0.9, s.yBack + 0.9, R / 2 + 0.7, facade - 0.7};
  for (int i = 0; i < p.walkers; ++i) {
    const double x = uniformReal(rng, 5, L - 5);
    std::vector<Eigen::Vector2d> waypoints;
    if (p.interaction == "high" && i % 2 == 1) {
      waypoints = {{x, -facade + 0.4}, {x + uniformReal(rng, -1, 1), -R / 2 - 0.4}};
    } else {
      const double lane = p.interaction == "high" ? lanes[static_cast<size_t>(i / 2 % 2)]
                                                  : lanes[static_cast<size_t>(i % 4)];
      waypoints = {{x, lane}, {std::min(L, x + uniformReal(rng, 20, 40)), lane}};
    }
    const double length = (waypoints[1] - waypoints[0]).norm();
    scene.agents.push_back(
        makePerson(id++, FloorPath(waypoints, p.speed, uniformReal(rng, 0, 2 * length)), p.stride,
                   textures, rng));
  }
  for (int i = 0; i < p.standing; ++i) {
    const double y = (rng() % 2 ? 1 : -1) * (rng() % 2 ? R / 2 + 0.6 : facade - 0.6);
    scene.agents.push_back(makePerson(id++, FloorPath({{uniformReal(rng, 5, L - 5), y}}, 0.0),
                                      p.stride, textures, rng));
  }
}

/// Cars: round the block (right-hand traffic: +x on the right lane), evenly spread, the lane
/// centres a car's width plus a gap from the parked cars; parked cars in the parking strips, at
/// least 6 m apart (bumper to bumper about 1.5 m).
void addStreetCars(Scene& scene, const CarOptions& c, const StreetLayout& s, uint16_t& id,
                   TextureLibrary& textures, std::mt19937_64& rng) {
  const double L = s.L, R = s.R;
  const double lane = R / 2 - 3.3;
  const std::vector<Eigen::Vector2d> block = {
      {-40, -lane}, {L + 40, -lane}, {L + 40, lane}, {-40, lane}};
  const double loop = FloorPath(block, 1.0, 0.0, FloorPath::Mode::Loop).length();
  for (int i = 0; i < c.driving; ++i) {
    const double offset = loop * (i + uniformReal(rng, 0, 0.5)) / c.driving;
    scene.agents.push_back(makeCar(
        id++, FloorPath(block, c.speed, offset, FloorPath::Mode::Loop, 3.0), textures, rng));
  }
  std::vector<double> taken[2];
  for (int i = 0, tries = 0; i < c.parked && tries < 1000; ++tries) {
    const int side = static_cast<int>(rng() % 2);
    const double x = uniformReal(rng, 8, L - 8);
    auto& xs = taken[side];
    if (std::any_of(xs.begin(), xs.end(), [&](double t) { return std::abs(t - x) < 6; })) continue;
    xs.push_back(x);
    const double y = (side ? 1 : -1) * (R / 2 - 1.1);
    scene.agents.push_back(makeCar(id++, FloorPath({{x, y}}, 0.0), textures, rng));
    ++i;
  }
}

}  // namespace

Scene buildStreetScene(const ScenarioOptions& o, TextureLibrary& textures, std::mt19937_64& rng) {
  const StreetLayout s(o.world);
  if (s.L < 20 || s.R < 9 || s.S < 3)
    throw std::invalid_argument(
        "street: street_length >= 20, road_width >= 9 and sidewalk_width >= 3 m are needed "
        "for the lanes, parking strips and the robot's lanes on the sidewalk");
  Scene scene;
  addStreetStatics(scene.static_mesh, s, textures, rng);
  scene.route = {{5, s.yOut}, {s.L - 5, s.yOut}, {s.L - 5, s.yBack}, {5, s.yBack}};
  scene.orbit_centre = {s.L / 2, 0};
  scene.background = {235, 206, 170};  // a pale blue sky
  uint16_t id = 1;
  addStreetPeople(scene, o.people, s, id, textures, rng);
  addStreetCars(scene, o.cars, s, id, textures, rng);
  return scene;
}

}  // namespace dynslam::sim
