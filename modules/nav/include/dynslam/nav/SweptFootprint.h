#pragma once
// Where a moving object is and will be, as obstacle points a reactive navigator can take: rings
// around its footprint's centre, repeated up its height, at the positions its constant-velocity
// prediction reaches over a horizon. The rings' outline is the swept area's; a robot cannot reach
// the inside without crossing a ring, so the inside needs no points.
#include <Eigen/Core>

#include <vector>

namespace dynslam::nav {

/// A moving object on the floor, in the navigation frame (x, y; z up from the floor).
struct Footprint {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();    ///< m
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< m/s
  double radius = 0.25;                                ///< m
  double top = 1.7;                                    ///< m above the floor
};

struct FootprintSampling {
  double spacing_m = 0.1;      ///< between points on a ring and between rings along the sweep
  double height_step_m = 0.3;  ///< between a ring's copies up the object
  double bottom_m = 0.05;      ///< the lowest copy's height (a navigator drops points near 0)
  double max_height_m = 2.0;   ///< no copy above this
};

/// Appends the footprint's rings from now to `horizon_s` ahead (now only when 0), navigation
/// frame, z above the floor.
void appendSweptFootprint(const Footprint& footprint, double horizon_s,
                          const FootprintSampling& sampling, std::vector<Eigen::Vector3f>& out);

}  // namespace dynslam::nav
