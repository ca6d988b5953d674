#include "dynslam/nav/SweptFootprint.h"

#include <algorithm>
#include <cmath>

namespace dynslam::nav {

void appendSweptFootprint(const Footprint& f, double horizon_s, const FootprintSampling& s,
                          std::vector<Eigen::Vector3f>& out) {
  const double spacing = std::max(s.spacing_m, 1e-3);
  const double sweep = f.velocity.norm() * std::max(horizon_s, 0.0);
  const int rings = 1 + static_cast<int>(std::ceil(sweep / spacing));
  const int around = std::max(8, static_cast<int>(std::ceil(2 * M_PI * f.radius / spacing)));
  const double top = std::min(f.top, s.max_height_m);
  std::vector<double> heights{s.bottom_m};
  for (double z = s.bottom_m + s.height_step_m; z <= top + 1e-9 && s.height_step_m > 0;
       z += s.height_step_m)
    heights.push_back(z);
  out.reserve(out.size() + static_cast<std::size_t>(rings * around) * heights.size());
  for (int r = 0; r < rings; ++r) {
    const double t = rings == 1 ? 0.0 : horizon_s * r / (rings - 1);
    const Eigen::Vector2d c = f.centre + f.velocity * t;
    for (int k = 0; k < around; ++k) {
      const double a = 2 * M_PI * k / around;
      const float x = static_cast<float>(c.x() + f.radius * std::cos(a));
      const float y = static_cast<float>(c.y() + f.radius * std::sin(a));
      for (double z : heights) out.emplace_back(x, y, static_cast<float>(z));
    }
  }
}

}  // namespace dynslam::nav
