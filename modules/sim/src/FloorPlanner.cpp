#include "dynslam/sim/FloorPlanner.h"

#include "dynslam/sim/Random.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
Eigen::Vector2d left(const Eigen::Vector2d& d) { return {-d.y(), d.x()}; }

/// Clear cell centres within `radius` of `centre`: where a fallback candidate may start.
std::vector<Eigen::Vector2d> regionCells(const FloorMap& map, const Eigen::Vector2d& centre,
                                         double radius) {
  std::vector<Eigen::Vector2d> cells;
  for (int r = 0; r < map.rows(); ++r)
    for (int c = 0; c < map.cols(); ++c)
      if (map.clear().at<uint8_t>(r, c) && (map.cellCentre(r, c) - centre).norm() <= radius)
        cells.push_back(map.cellCentre(r, c));
  if (cells.empty())
    throw std::runtime_error("floor planner: no clear floor within " + std::to_string(radius) +
                             " m of the region centre");
  return cells;
}

/// Smallest distance between the path (relative to centre) and the camera over the track.
double cameraDistance(const FloorPath& path, const CameraTrack& camera,
                      const Eigen::Vector2d& centre) {
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < camera.t.size(); ++k) {
    Eigen::Vector2d xy;
    double heading;
    path.at(camera.t[k], xy, heading);
    nearest = std::min(nearest, (xy + centre - camera.xy[k]).norm());
  }
  return nearest;
}

/// Smallest distance between two agents' paths at the frame times.
double pathDistance(const FloorPath& a, const std::vector<FloorPath>& others,
                    const std::vector<double>& times) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const double t : times) {
    Eigen::Vector2d p, q;
    double heading;
    a.at(t, p, heading);
    for (const auto& other : others) {
      other.at(t, q, heading);
      nearest = std::min(nearest, (p - q).norm());
    }
  }
  return nearest;
}

/// How well a candidate keeps its distances: above 1e3 when it keeps both (then the larger
/// `size` wins), otherwise the worse of the two as a fraction of what it should keep.
double candidateScore(double camera_distance, double camera_clearance, double agent_distance,
                      double separation, double size) {
  const double worst = std::min(camera_distance / camera_clearance, agent_distance / separation);
  return worst >= 1 ? 1e3 + size : worst;
}

/// Clear run along `dir` of a band `half_width` wide on each side of the line through `p`.
double bandRun(const FloorMap& map, const Eigen::Vector2d& p, const Eigen::Vector2d& dir,
               double half_width, double max_length) {
  double run = max_length;
  for (double o = -half_width; o <= half_width + 1e-9; o += map.cellSize() / 2) {
    const Eigen::Vector2d q = p + o * left(dir);
    run = map.isClear(q) ? std::min(run, map.clearRun(q, dir, max_length)) : -1.0;
    if (run < 0) break;
  }
  return run;
}

}  // namespace

Eigen::Vector2d chooseRegionCentre(const FloorMap& map, double radius) {
  cv::Mat seen;
  map.views().convertTo(seen, CV_32F);
  seen.setTo(0, map.clear() == 0);
  const int r = std::max(1, static_cast<int>(std::lround(radius / map.cellSize())));
  const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1});
  cv::Mat kernel;
  disc.convertTo(kernel, CV_32F);
  cv::Mat around;
  cv::filter2D(seen, around, CV_32F, kernel, {-1, -1}, 0, cv::BORDER_CONSTANT);
  around.setTo(-1, map.clear() == 0);
  double best;
  cv::Point at;
  cv::minMaxLoc(around, nullptr, &best, nullptr, &at);
  if (best < 0) throw std::runtime_error("floor planner: the floor map has no clear cell");
  return map.cellCentre(at.y, at.x);
}

namespace {

/// One greedy placement of everybody. Restart 0 gives each walker the longest candidate that
/// keeps its distances; later restarts a random one of those, so that a first walker hogging
/// the middle of a narrow floor does not leave the others no room.
struct PeoplePlan {
  std::vector<FloorPath> paths;
  double score = -1;  ///< the worst candidateScore of its people
  double longest_chord = 0;
  int walker_without_chord = -1;  ///< >= 0: this walker found no chord at all
};

/// planPeopleOnce's steps, sharing what every step reads.
class PeoplePlanner {
 public:
  PeoplePlanner(const PeopleOptions& people, const FloorMap& map,
                const std::vector<Eigen::Vector2d>& cells, const Eigen::Vector2d& centre,
                const CameraTrack& camera, const FloorPlanOptions& o, std::mt19937_64& rng)
      : people_(people),
        map_(map),
        cells_(cells),
        centre_(centre),
        camera_(camera),
        o_(o),
        rng_(rng) {}

  PeoplePlan plan(int restart) {
    const double base = uniformReal(rng_, 0, M_PI);
    PeoplePlan plan;
    plan.score = std::numeric_limits<double>::infinity();
    for (int i = 0; i < people_.walkers; ++i) {
      auto candidates = walkerCandidates(i, base, plan);
      if (candidates.empty()) {
        plan.walker_without_chord = i;
        return plan;
      }
      const auto& chosen = choose(candidates, restart);
      plan.score = std::min(plan.score, chosen.second);
      plan.paths.push_back(chosen.first);
    }
    for (int j = 0; j < people_.standing; ++j) addStanding(plan);
    return plan;
  }

 private:
  using Candidate = std::pair<FloorPath, double>;  // with its score

  Eigen::Vector2d pick() {
    return cells_[static_cast<size_t>(uniformReal(rng_, 0, cells_.size()))];
  }

  /// Walker i's possible paths: first the mode's own layout around the centre, then any chord
  /// through the region.
  std::vector<Candidate> walkerCandidates(int i, double base, PeoplePlan& plan) {
    const double R = o_.region_radius;
    std::vector<Candidate> candidates;
    for (int attempt = 0; attempt < 60; ++attempt) {
      double angle;
      Eigen::Vector2d through;
      if (attempt < 20 && people_.interaction == "high") {
        angle = base + M_PI * i / people_.walkers + uniformReal(rng_, -0.2, 0.2);
        through = centre_ + left(unit(angle)) * uniformReal(rng_, -0.3, 0.3);
      } else if (attempt < 20) {
        angle = base + (attempt > 0 ? uniformReal(rng_, -0.1, 0.1) : 0.0);
        const double lane = std::clamp((i - (people_.walkers - 1) / 2.0) * 0.9, -0.8 * R, 0.8 * R);
        through = centre_ + left(unit(angle)) * (lane + uniformReal(rng_, -0.1, 0.1));
      } else {
        angle = uniformReal(rng_, 0, M_PI);
        through = pick();
      }
      if (!map_.isClear(through)) continue;
      const Eigen::Vector2d dir = unit(angle);
      double ahead = map_.clearRun(through, dir, R), behind = map_.clearRun(through, -dir, R);
      plan.longest_chord = std::max(plan.longest_chord, ahead + behind);
      if (ahead + behind < o_.min_walk_length) continue;
      if (attempt >= 20 && attempt % 2 == 1) {
        // Part of the chord only: on a narrow floor, walkers pacing different stretches of one
        // aisle keep apart where whole chords would make them walk through each other.
        const double length = uniformReal(rng_, o_.min_walk_length, ahead + behind);
        const double start = uniformReal(rng_, 0, ahead + behind - length);  // from the back end
        ahead = length + start - behind;
        behind = behind - start;
      }
      const Eigen::Vector2d a = through - behind * dir, b = through + ahead * dir;
      FloorPath path({a - centre_, b - centre_}, people_.speed,
                     uniformReal(rng_, 0, 2 * (ahead + behind)), FloorPath::Mode::BackAndForth,
                     o_.turn_length);
      const double score =
          candidateScore(cameraDistance(path, camera_, centre_), o_.camera_clearance,
                         pathDistance(path, plan.paths, camera_.t), o_.separation, ahead + behind);
      candidates.emplace_back(std::move(path), score);
    }
    return candidates;
  }

  /// The best candidate; on a restart, a random one of those that keep every distance.
  const Candidate& choose(const std::vector<Candidate>& candidates, int restart) {
    auto chosen = std::max_element(candidates.begin(), candidates.end(),
                                   [](auto& x, auto& y) { return x.second < y.second; });
    if (restart > 0 && chosen->second >= 1e3) {
      std::vector<size_t> keeping;
      for (size_t c = 0; c < candidates.size(); ++c)
        if (candidates[c].second >= 1e3) keeping.push_back(c);
      chosen =
          candidates.begin() + keeping[static_cast<size_t>(uniformReal(rng_, 0, keeping.size()))];
    }
    return *chosen;
  }

  void addStanding(PeoplePlan& plan) {
    std::optional<FloorPath> best;
    double best_score = -1;
    for (int attempt = 0; attempt < 60; ++attempt) {
      FloorPath spot({pick() - centre_}, 0.0);
      // Farther than 2 m from everybody is as good as any distance.
      const double room = std::min(2.0, pathDistance(spot, plan.paths, camera_.t));
      const double score = candidateScore(cameraDistance(spot, camera_, centre_),
                                          o_.camera_clearance, room, o_.separation, room);
      if (score > best_score) best = spot, best_score = score;
    }
    plan.score = std::min(plan.score, best_score);
    plan.paths.push_back(*best);
  }

  const PeopleOptions& people_;
  const FloorMap& map_;
  const std::vector<Eigen::Vector2d>& cells_;
  const Eigen::Vector2d& centre_;
  const CameraTrack& camera_;
  const FloorPlanOptions& o_;
  std::mt19937_64& rng_;
};

PeoplePlan planPeopleOnce(const PeopleOptions& people, const FloorMap& map,
                          const std::vector<Eigen::Vector2d>& cells, const Eigen::Vector2d& centre,
                          const CameraTrack& camera, const FloorPlanOptions& o, int restart,
                          std::mt19937_64& rng) {
  return PeoplePlanner(people, map, cells, centre, camera, o, rng).plan(restart);
}

}  // namespace

namespace {

/// The best of 20 restarts; nullopt when a walker found no chord of min_walk_length (`failed`
/// then says which and the longest chord seen).
std::optional<std::vector<FloorPath>> planPeopleRestarts(
    const PeopleOptions& people, const FloorMap& map, const std::vector<Eigen::Vector2d>& cells,
    const Eigen::Vector2d& centre, const CameraTrack& camera, const FloorPlanOptions& o,
    std::mt19937_64& rng, PeoplePlan& failed) {
  PeoplePlan best;
  for (int restart = 0; restart < 20; ++restart) {
    PeoplePlan plan = planPeopleOnce(people, map, cells, centre, camera, o, restart, rng);
    if (plan.walker_without_chord >= 0)
      failed = std::move(plan);
    else if (plan.score > best.score)  // keeping distances: most walking; else the least bad
      best = std::move(plan);
  }
  if (best.score < 0) return std::nullopt;
  return std::move(best.paths);
}

std::string noChordMessage(const PeoplePlan& failed, const FloorPlanOptions& o, const FloorMap& map,
                           size_t cells) {
  std::ostringstream msg;
  msg << "walker " << failed.walker_without_chord + 1 << " found no clear straight path of "
      << o.min_walk_length << " m within " << o.region_radius
      << " m of the region centre in 20 tries (the longest clear chord was " << failed.longest_chord
      << " m; " << cells << " clear cells of " << map.cellSize() << " m)";
  return msg.str();
}

}  // namespace

std::vector<FloorPath> planPeople(const PeopleOptions& people, const FloorMap& map,
                                  const Eigen::Vector2d& centre, const CameraTrack& camera,
                                  const FloorPlanOptions& o, std::mt19937_64& rng,
                                  std::vector<std::string>* fallbacks) {
  const std::vector<Eigen::Vector2d> cells = regionCells(map, centre, o.region_radius);  // throws
  PeopleOptions p = people;
  FloorPlanOptions q = o;
  std::string firstFailure;
  for (PeoplePlan failed;;) {
    if (auto paths = planPeopleRestarts(p, map, cells, centre, camera, q, rng, failed)) {
      if (fallbacks && !firstFailure.empty()) {
        std::ostringstream msg;
        msg << "floor planner: " << firstFailure << "; placed " << p.walkers
            << " walkers on paths of at least " << q.min_walk_length << " m and " << p.standing
            << " standing people instead (asked for " << people.walkers << " and "
            << people.standing << ")";
        fallbacks->push_back(msg.str());
      }
      return *paths;
    }
    if (firstFailure.empty()) firstFailure = noChordMessage(failed, q, map, cells.size());
    // Shorter walks first (down to shortest_walk), then one walker fewer, standing instead.
    if (q.min_walk_length > o.shortest_walk + 1e-9) {
      q.min_walk_length = std::max(o.shortest_walk, q.min_walk_length - 0.2);
    } else if (p.walkers > 0) {
      --p.walkers;
      ++p.standing;
      q.min_walk_length = o.min_walk_length;
    } else {
      throw std::runtime_error("floor planner: " + firstFailure);  // standing people always fit
    }
  }
}

std::vector<FloorPath> planCars(const CarOptions& cars, const FloorMap& map,
                                const Eigen::Vector2d& centre, const CameraTrack& camera,
                                const FloorPlanOptions& o, std::mt19937_64& rng) {
  std::vector<FloorPath> paths;
  if (cars.driving + cars.parked <= 0) return paths;
  // A car needs more floor than people do: it may use any clear floor within four car
  // lengths of the centre.
  const double L = o.car_length, W = o.car_width, R = std::max(o.region_radius, 4 * L);
  const std::vector<Eigen::Vector2d> cells = regionCells(map, centre, R);
  const auto pick = [&] { return cells[static_cast<size_t>(uniformReal(rng, 0, cells.size()))]; };
  for (int i = 0; i < cars.driving; ++i) {
    std::optional<FloorPath> best;
    double longest = 0;
    for (int attempt = 0; attempt < 60; ++attempt) {
      const Eigen::Vector2d through = pick(), dir = unit(uniformReal(rng, 0, M_PI));
      // Two lanes 1.2 W apart, each as wide as a car: a band of 1.7 W around the axis.
      const double half = 1.1 * W, ahead = bandRun(map, through, dir, half, R) - L / 2,
                   behind = bandRun(map, through, -dir, half, R) - L / 2;
      longest = std::max(longest, ahead + behind);
      if (ahead + behind < 2 * L || best) continue;
      const Eigen::Vector2d side = left(dir) * 0.6 * W;
      const Eigen::Vector2d s = through - behind * dir - centre, e = through + ahead * dir - centre;
      FloorPath path({s - side, e - side, e + side, s + side}, cars.speed,
                     uniformReal(rng, 0, 2 * (ahead + behind)), FloorPath::Mode::Loop, L / 2);
      if (cameraDistance(path, camera, centre) >= o.camera_clearance + L / 2) best = path;
    }
    if (!best)
      throw std::runtime_error("floor planner: no room for driving car " + std::to_string(i + 1) +
                               ": it needs two clear lanes of " + std::to_string(2 * L) +
                               " m clear of the camera; the longest found was " +
                               std::to_string(std::max(0.0, longest)) + " m");
    paths.push_back(*best);
  }
  std::vector<Eigen::Vector2d> parked;
  for (int i = 0; i < cars.parked; ++i) {
    std::optional<Eigen::Vector2d> spot;
    for (int attempt = 0; attempt < 200 && !spot; ++attempt) {
      const Eigen::Vector2d p = pick();  // heading 0: length along x
      bool fits = bandRun(map, p, Eigen::Vector2d::UnitX(), W / 2, L / 2) >= L / 2 &&
                  bandRun(map, p, -Eigen::Vector2d::UnitX(), W / 2, L / 2) >= L / 2;
      for (const auto& q : parked)  // side by side or nose to tail, never overlapping
        fits = fits && (std::abs(q.x() - p.x()) >= L + 0.3 || std::abs(q.y() - p.y()) >= W + 0.3);
      fits = fits && cameraDistance(FloorPath({p - centre}, 0.0), camera, centre) >=
                         o.camera_clearance + L / 2;
      if (fits) spot = p;
    }
    if (!spot)
      throw std::runtime_error("floor planner: no clear spot of " + std::to_string(L) + " x " +
                               std::to_string(W) + " m for parked car " + std::to_string(i + 1));
    parked.push_back(*spot);
    paths.emplace_back(std::vector<Eigen::Vector2d>{*spot - centre}, 0.0);
  }
  return paths;
}

}  // namespace dynslam::sim
