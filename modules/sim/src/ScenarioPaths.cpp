#include "dynslam/sim/ScenarioPaths.h"

#include "dynslam/sim/Random.h"

#include <algorithm>
#include <cmath>

namespace dynslam::sim {

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
