#pragma once
// The run seen from above, as a video (top.avi, one picture per navigation step) and a summary
// picture (top.png): static obstacles grey, goals numbered, the robot's true path green and its
// estimated path blue, people red with the obstacle points the navigator was given (their
// predicted footprints) light red.
#include "nav_demo/StaticFootprint.h"

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <opencv2/videoio.hpp>

#include <string>
#include <vector>

namespace dynslam::navdemo {

struct TopViewState {
  double t = 0;
  std::size_t goal = 0;
  Eigen::Vector3d robot = Eigen::Vector3d::Zero();  ///< true x, y, yaw, world
  bool estimated_valid = false;
  Eigen::Vector3d estimated = Eigen::Vector3d::Zero();
  double robot_radius = 0.3;
  std::vector<Eigen::Vector2d> people;
  double person_radius = 0.25;
  std::vector<Eigen::Vector2d> obstacles;  ///< what the navigator sensed, world x, y
};

class TopView {
 public:
  /// `video`: "" for none.
  TopView(const StaticFootprint& statics, std::vector<Eigen::Vector2d> goals,
          const std::string& video, double fps);
  void add(const TopViewState& state);
  /// The paths so far over the static map and the goals (reached green, missed red), the
  /// people's paths faint red.
  void writeSummary(const std::string& png, const std::vector<bool>& reached) const;

 private:
  cv::Point pixel(const Eigen::Vector2d& world) const;
  cv::Mat background() const;

  const StaticFootprint& statics_;
  std::vector<Eigen::Vector2d> goals_;
  double scale_;  // pixels per metre
  cv::Mat base_;
  cv::VideoWriter video_;
  std::vector<cv::Point> true_path_, estimated_path_;
  std::vector<std::vector<cv::Point>> people_paths_;  // by the order of TopViewState::people
};

}  // namespace dynslam::navdemo
