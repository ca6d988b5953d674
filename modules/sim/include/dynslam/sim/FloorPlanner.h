#pragma once
// Where the Augmenter's people and cars go: paths on the clear cells of a real floor
// (FloorMap), in the part of it the camera sees most, away from the camera itself. The
// counterpart of makePeoplePaths (which fills a synthetic disc) for a floor that is whatever
// the real room left free: chords are cut to the clear cells, and the interaction modes keep
// their meaning where the free floor allows (high: lines through the centre at spread angles,
// so they cross; low: parallel lanes 0.9 m apart).
#include <dynslam/sim/FloorMap.h>
#include <dynslam/sim/FloorPath.h>
#include <dynslam/sim/ScenarioOptions.h>

#include <Eigen/Core>

#include <random>
#include <string>
#include <vector>

namespace dynslam::sim {

/// The camera's optical centre over the floor (map frame) at the frame times (s).
struct CameraTrack {
  std::vector<double> t;
  std::vector<Eigen::Vector2d> xy;
};

struct FloorPlanOptions {
  double region_radius = 2.0;     ///< m around the centre that paths may use
  double min_walk_length = 0.8;   ///< m; shorter clear chords are not used for walkers
  /// m; when no plan gives every walker min_walk_length, walks are shortened in 0.2 m steps
  /// down to this before a walker becomes a standing person.
  double shortest_walk = 0.4;
  double camera_clearance = 0.5;  ///< m kept between any agent and the camera at every frame
  double separation = 0.6;        ///< m kept between people at every frame (when possible)
  double turn_length = 0.3;       ///< m over which walkers turn round (FloorPath)
  double car_length = 4.8, car_width = 1.9;  ///< m; the largest car makeCar builds
};

/// The clear cell maximising the camera views summed over the clear cells within `radius` of
/// it. Throws std::runtime_error when the map has no clear cell.
Eigen::Vector2d chooseRegionCentre(const FloorMap& map, double radius);

/// Walkers then standing people. Paths are expressed relative to `centre` (the origin of the
/// frame the agents live in), the map and the camera track in map coordinates. Each walker
/// takes the longest of up to 60 candidate chords (spread angles first, then any angle through
/// any clear cell of the region, whole or in part) that keeps camera_clearance from the camera and
/// separation from the people placed before it at every frame; when none does, the one that comes
/// closest. Standing people take the candidate spot farthest from everybody. A floor with too
/// little room does not stop the plan: when no clear chord of min_walk_length exists, walks are
/// shortened (down to shortest_walk), then walkers become standing people one at a time, and
/// `fallbacks` (when given) receives one line saying what failed and what was placed instead.
/// Throws std::runtime_error when the region has no clear cell at all.
std::vector<FloorPath> planPeople(const PeopleOptions& people, const FloorMap& map,
                                  const Eigen::Vector2d& centre, const CameraTrack& camera,
                                  const FloorPlanOptions& options, std::mt19937_64& rng,
                                  std::vector<std::string>* fallbacks = nullptr);

/// Driving cars loop round a lane pair (out on one lane, back on the other, 1.2 widths apart,
/// at least two car lengths long); parked cars stand with heading 0 (FloorPath's heading of a
/// standing agent), apart from each other. Both need their whole footprint on clear floor
/// within four car lengths of `centre` (more than people's region_radius), and keep
/// camera_clearance plus half a car length from the camera. Cars and people are planned
/// independently (people may cross a driving car's lanes, as on a street). Throws
/// std::runtime_error naming what did not fit.
std::vector<FloorPath> planCars(const CarOptions& cars, const FloorMap& map,
                                const Eigen::Vector2d& centre, const CameraTrack& camera,
                                const FloorPlanOptions& options, std::mt19937_64& rng);

}  // namespace dynslam::sim
