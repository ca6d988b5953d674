#include "object_scoring.h"

#include <dynslam/core/HungarianAssignment.h>
#include <dynslam/core/Median.h>
#include <dynslam/viz/IdColours.h>

#include <Eigen/Core>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dynslam::bench {
namespace {

Eigen::Vector3d horizontal(const Eigen::Vector3d& v, const Eigen::Vector3d& up) {
  return v - v.dot(up) * up;
}

/// Each body's true world velocity per frame: central difference of its listed positions.
std::map<std::pair<int, std::size_t>, Eigen::Vector3d> trueVelocities(
    const std::vector<core::ObjectGroundTruthRow>& truth, int half_window) {
  std::map<int, std::vector<const core::ObjectGroundTruthRow*>> by_id;
  for (const auto& r : truth) by_id[r.id].push_back(&r);
  std::map<std::pair<int, std::size_t>, Eigen::Vector3d> out;
  for (auto& [id, rows] : by_id) {
    std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return a->frame < b->frame; });
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::size_t a = k >= std::size_t(half_window) ? k - half_window : 0;
      const std::size_t b = std::min(rows.size() - 1, k + half_window);
      const double dt = rows[b]->t - rows[a]->t;
      out[{id, rows[k]->frame}] = dt > 0 ? Eigen::Vector3d((rows[b]->T_world_object.translation() -
                                                            rows[a]->T_world_object.translation()) /
                                                           dt)
                                         : Eigen::Vector3d::Zero();
    }
  }
  return out;
}

}  // namespace

std::map<double, std::vector<core::ObjectState>> readObjectStates(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the object states '" + path + "'");
  std::map<double, std::vector<core::ObjectState>> out;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 || line.empty()) continue;  // the header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double t = 0;
    int measured = 0, moving = 0;
    core::ObjectState s;
    fields >> t >> s.id >> s.track_id >> s.category >> measured >> moving;
    for (auto* v : {&s.centre, &s.velocity, &s.extent}) fields >> (*v)(0) >> (*v)(1) >> (*v)(2);
    s.covariance.setZero();
    for (int i = 0; i < 6; ++i) {
      double sigma = 0;
      fields >> sigma;
      s.covariance(i, i) = sigma * sigma;
    }
    fields >> s.up(0) >> s.up(1) >> s.up(2);
    if (!fields)
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": not a row of 24 fields (t_s,id,...,up_z)");
    s.measured = measured != 0;
    s.moving = moving != 0;
    out[t].push_back(std::move(s));
  }
  return out;
}

ObjectScore scoreObjectStates(const std::vector<core::ObjectGroundTruthRow>& truth,
                              const core::Trajectory& true_camera,
                              const core::Trajectory& estimated_camera,
                              const std::map<double, std::vector<core::ObjectState>>& states,
                              const ObjectScoringOptions& options) {
  const core::ObjectGroundTruthIndex index(truth);
  const auto velocities = trueVelocities(truth, options.velocity_frames);
  const Eigen::Vector3d up_world = Eigen::Vector3d::UnitZ();
  static const std::vector<core::ObjectState> kNone;

  ObjectScore score;
  std::map<int, int> last_state;             // person -> state id paired last
  std::map<int, double> gap_start, longest;  // person -> stretch without a state
  std::vector<double> intervals;
  for (std::size_t f = 1; f < true_camera.size(); ++f)
    intervals.push_back(true_camera[f].t - true_camera[f - 1].t);
  score.frame_interval = core::upperMedian(intervals);

  for (const auto& camera : true_camera) {
    const auto& bodies = index.atTime(camera.t, options.stamp_tolerance);
    if (bodies.empty()) continue;
    const core::StampedPose* estimated =
        core::poseNear(estimated_camera, camera.t, options.stamp_tolerance);
    auto found = states.lower_bound(camera.t - options.stamp_tolerance);
    const auto& here = estimated && found != states.end() &&
                               std::abs(found->first - camera.t) <= options.stamp_tolerance
                           ? found->second
                           : kNone;
    // Both sides in their camera's frame; up is the true world's z seen from the true camera.
    const Eigen::Isometry3d true_inverse = camera.T_world_body.inverse();
    const Eigen::Vector3d up = true_inverse.linear() * up_world;
    Eigen::MatrixXd cost(bodies.size(), here.size());
    std::vector<Eigen::Vector3d> body_c, state_c;
    for (const auto& b : bodies) body_c.push_back(true_inverse * b.T_world_object.translation());
    if (estimated) {
      const Eigen::Isometry3d est_inverse = estimated->T_world_body.inverse();
      for (const auto& s : here) state_c.push_back(est_inverse * s.centre);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = 0; j < here.size(); ++j) {
        const double d = horizontal(body_c[i] - state_c[j], up).norm();
        cost(Eigen::Index(i), Eigen::Index(j)) = d <= options.gate_m ? d : 1e6;
      }
    const std::vector<int> pairing =
        here.empty() ? std::vector<int>(bodies.size(), -1) : core::solveMinCostAssignment(cost);

    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const auto& b = bodies[i];
      if (b.category != "person" || !b.moving || b.visible_fraction < options.min_visible) continue;
      ++score.scored;
      if (!longest.count(b.id)) {
        longest[b.id] = 0;
        ++score.persons;
      }
      const int j = pairing[i];
      if (j < 0 || cost(Eigen::Index(i), j) > options.gate_m) {
        if (!gap_start.count(b.id)) gap_start[b.id] = camera.t;
        longest[b.id] = std::max(longest[b.id], camera.t - gap_start[b.id] + score.frame_interval);
        continue;
      }
      gap_start.erase(b.id);
      ++score.paired;
      score.position_errors.push_back(cost(Eigen::Index(i), j));
      const auto& s = here[std::size_t(j)];
      const Eigen::Vector3d v_est = estimated->T_world_body.linear().transpose() * s.velocity;
      const Eigen::Vector3d v_true = true_inverse.linear() * velocities.at({b.id, b.frame});
      score.velocity_errors.push_back(horizontal(v_est - v_true, up).norm());
      auto last = last_state.find(b.id);
      if (last != last_state.end() && last->second != s.id) ++score.id_switches;
      last_state[b.id] = s.id;
    }
    // A person out of view (or too hidden) ends its stretch without a state.
    for (auto it = gap_start.begin(); it != gap_start.end();) {
      const bool inView = std::any_of(bodies.begin(), bodies.end(), [&](const auto& b) {
        return b.id == it->first && b.visible_fraction >= options.min_visible;
      });
      it = inView ? std::next(it) : gap_start.erase(it);
    }
  }
  for (const auto& [id, gap] : longest) score.longest_gaps.push_back(gap);
  return score;
}

void pool(ObjectScore& a, const ObjectScore& b) {
  a.position_errors.insert(a.position_errors.end(), b.position_errors.begin(),
                           b.position_errors.end());
  a.velocity_errors.insert(a.velocity_errors.end(), b.velocity_errors.begin(),
                           b.velocity_errors.end());
  a.longest_gaps.insert(a.longest_gaps.end(), b.longest_gaps.begin(), b.longest_gaps.end());
  a.scored += b.scored;
  a.paired += b.paired;
  a.id_switches += b.id_switches;
  a.persons += b.persons;
  if (a.frame_interval == 0) a.frame_interval = b.frame_interval;
}

void writeTopView(const std::string& path, const std::vector<core::ObjectGroundTruthRow>& truth,
                  const core::Trajectory& true_camera, const core::Trajectory& estimated_camera,
                  const std::map<double, std::vector<core::ObjectState>>& states,
                  const ObjectScoringOptions& options) {
  // Every point in the true world's x-y plane first, then one scale for all.
  std::vector<Eigen::Vector2d> camera;
  std::map<int, std::vector<Eigen::Vector2d>> people;
  struct Dot {
    Eigen::Vector2d p;
    int id;
    bool measured;
  };
  std::vector<Dot> dots;
  for (const auto& c : true_camera) camera.push_back(c.T_world_body.translation().head<2>());
  for (const auto& r : truth)
    if (r.category == "person" && r.moving)
      people[r.id].push_back(r.T_world_object.translation().head<2>());
  for (const auto& [t, here] : states) {
    const auto* truePose = core::poseNear(true_camera, t, options.stamp_tolerance);
    const auto* estPose = core::poseNear(estimated_camera, t, options.stamp_tolerance);
    if (!truePose || !estPose) continue;
    const Eigen::Isometry3d toTrue = truePose->T_world_body * estPose->T_world_body.inverse();
    for (const auto& s : here) dots.push_back({(toTrue * s.centre).head<2>(), s.id, s.measured});
  }
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  const auto grow = [&](const Eigen::Vector2d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const auto& p : camera) grow(p);
  for (const auto& [id, path] : people)
    for (const auto& p : path) grow(p);
  if (camera.empty()) throw std::runtime_error("nothing to draw into '" + path + "'");
  const int size = 900, margin = 40;
  const double scale = (size - 2 * margin) / std::max(0.5, (hi - lo).maxCoeff());
  const auto pixel = [&](const Eigen::Vector2d& p) {
    return cv::Point(int(margin + (p.x() - lo.x()) * scale),
                     int(size - margin - (p.y() - lo.y()) * scale));
  };
  cv::Mat image(size, size, CV_8UC3, cv::Scalar(255, 255, 255));
  for (const auto& [id, path] : people)
    for (std::size_t k = 1; k < path.size(); ++k)
      cv::line(image, pixel(path[k - 1]), pixel(path[k]), cv::Scalar(170, 170, 170), 5,
               cv::LINE_AA);
  for (const auto& d : dots) {
    // State ids start at 0, which colourForId keeps black for the static scene.
    cv::circle(image, pixel(d.p), 2, viz::colourForId(d.id + 1), d.measured ? cv::FILLED : 1,
               cv::LINE_AA);
  }
  for (std::size_t k = 1; k < camera.size(); ++k)
    cv::line(image, pixel(camera[k - 1]), pixel(camera[k]), cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  const double metre = scale;
  cv::line(image, {margin, size - 15}, {int(margin + metre), size - 15}, cv::Scalar(0, 0, 0), 2);
  cv::putText(
      image, "1 m   grey: true walkers   dots: object states (hollow: predicted)   black: camera",
      {margin, size - 22}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  if (!cv::imwrite(path, image)) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace dynslam::bench
