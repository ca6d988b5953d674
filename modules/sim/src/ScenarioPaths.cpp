#include "dynslam/sim/ScenarioPaths.h"

#include "dynslam/sim/Random.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dynslam::sim {

std::vector<std::vector<Eigen::Vector2d>> parseWaypointList(const std::string& text) {
  std::vector<std::vector<Eigen::Vector2d>> groups;
  if (text.find_first_not_of(" \t") == std::string::npos) return groups;
  std::istringstream all(text);
  for (std::string group; std::getline(all, group, '|');) {
    std::istringstream points(group);
    groups.emplace_back();
    for (std::string point; points >> point;) {
      double x = 0, y = 0;
      char comma = 0, extra = 0;
      std::istringstream xy(point);
      if (!(xy >> x >> comma >> y) || comma != ',' || (xy >> extra) || !std::isfinite(x) ||
          !std::isfinite(y))
        throw std::invalid_argument("'" + point + "' is not a point x,y (metres)");
      groups.back().emplace_back(x, y);
    }
    if (groups.back().empty())
      throw std::invalid_argument("an empty group in '" + text + "' (two '|' in a row?)");
  }
  return groups;
}

void addListedAgents(const ScenarioOptions& o, std::vector<Agent>& agents, TextureLibrary& textures,
                     std::mt19937_64& rng) {
  uint16_t id = 1;
  for (const auto& a : agents) id = std::max<uint16_t>(id, a.id + 1);
  for (auto& points : parseWaypointList(o.people.waypoints))
    agents.push_back(makePerson(id++, FloorPath(std::move(points), o.people.speed), o.people.stride,
                                textures, rng));
  for (auto& points : parseWaypointList(o.cars.waypoints))
    agents.push_back(
        makeCar(id++, FloorPath(std::move(points), o.cars.speed, 0.0, FloorPath::Mode::Loop, 3.0),
                textures, rng));
}

std::vector<FloorPath> makePeoplePaths(const PeopleOptions& p, double radius,
                                       std::mt19937_64& rng) {
  std::vector<FloorPath> paths;
  const double lineAngle = uniformReal(rng, 0, M_PI);
  for (int i = 0; i < p.walkers; ++i) {
    Eigen::Vector2d a, b;
    if (p.interaction == "high") {
      // Diameters at evenly spread angles, shifted a little off the centre so bodies do not
      // meet exactly there; they still cross each other and the camera's line of sight.
      const double angle =
          lineAngle + M_PI * i / std::max(1, p.walkers) + uniformReal(rng, -0.2, 0.2);
      const Eigen::Vector2d dir(std::cos(angle), std::sin(angle)), side(-dir.y(), dir.x());
      const Eigen::Vector2d shift = side * uniformReal(rng, -0.3, 0.3);
      a = shift - dir * radius;
      b = shift + dir * radius;
    } else {
      // Parallel lanes 0.9 m apart: nobody crosses anybody.
      const Eigen::Vector2d dir(std::cos(lineAngle), std::sin(lineAngle)), side(-dir.y(), dir.x());
      const double offset =
          std::clamp((i - (p.walkers - 1) / 2.0) * 0.9, -0.8 * radius, 0.8 * radius);
      const double half = std::sqrt(std::max(0.25, radius * radius - offset * offset));
      a = side * offset - dir * half;
      b = side * offset + dir * half;
    }
    const double length = (b - a).norm();
    paths.emplace_back(std::vector<Eigen::Vector2d>{a, b}, p.speed,
                       uniformReal(rng, 0, 2 * length));
  }
  for (int i = 0; i < p.standing; ++i) {
    const double angle = uniformReal(rng, 0, 2 * M_PI), r = uniformReal(rng, 0.3, 0.8) * radius;
    paths.emplace_back(std::vector<Eigen::Vector2d>{{r * std::cos(angle), r * std::sin(angle)}},
                       0.0);
  }
  return paths;
}

}  // namespace dynslam::sim
