#include "nav_demo/TopView.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::navdemo {
namespace {

const cv::Scalar kTrue(60, 170, 60), kEstimated(200, 110, 30), kPerson(50, 50, 220),
    kObstacle(170, 170, 250), kGoal(30, 30, 30);

}  // namespace

TopView::TopView(const StaticFootprint& statics, std::vector<Eigen::Vector2d> goals,
                 const std::string& video, double fps)
    : statics_(statics), goals_(std::move(goals)) {
  const double widthM = statics.cols() * statics.cell(), heightM = statics.rows() * statics.cell();
  scale_ = std::min(1000.0 / widthM, 800.0 / heightM);
  base_ = background();
  if (!video.empty()) {
    video_.open(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps, base_.size());
    if (!video_.isOpened()) throw std::runtime_error("cannot write the video '" + video + "'");
  }
}

cv::Point TopView::pixel(const Eigen::Vector2d& w) const {
  // x to the right, y up.
  const Eigen::Vector2d p = (w - statics_.origin()) * scale_;
  return {static_cast<int>(std::lround(p.x())),
          static_cast<int>(std::lround(statics_.rows() * statics_.cell() * scale_ - p.y()))};
}

cv::Mat TopView::background() const {
  const int w = static_cast<int>(std::ceil(statics_.cols() * statics_.cell() * scale_));
  const int h = static_cast<int>(std::ceil(statics_.rows() * statics_.cell() * scale_));
  cv::Mat img(h + (h % 2), w + (w % 2), CV_8UC3, cv::Scalar(255, 255, 255));
  const int r = std::max(1, static_cast<int>(std::lround(statics_.cell() * scale_ / 2)));
  for (const auto& c : statics_.occupiedCells()) cv::circle(img, pixel(c), r, {150, 150, 150}, -1);
  for (std::size_t i = 0; i < goals_.size(); ++i) {
    cv::drawMarker(img, pixel(goals_[i]), kGoal, cv::MARKER_CROSS, 16, 2);
    cv::putText(img, std::to_string(i + 1), pixel(goals_[i]) + cv::Point(6, -6),
                cv::FONT_HERSHEY_SIMPLEX, 0.6, kGoal, 2);
  }
  return img;
}

void TopView::add(const TopViewState& s) {
  true_path_.push_back(pixel(s.robot.head<2>()));
  if (s.estimated_valid) estimated_path_.push_back(pixel(s.estimated.head<2>()));
  people_paths_.resize(std::max(people_paths_.size(), s.people.size()));
  for (std::size_t i = 0; i < s.people.size(); ++i) people_paths_[i].push_back(pixel(s.people[i]));
  if (!video_.isOpened()) return;
  cv::Mat img = base_.clone();
  for (const auto& o : s.obstacles) cv::circle(img, pixel(o), 2, kObstacle, -1);
  const auto radius = [&](double m) {
    return std::max(2, static_cast<int>(std::lround(m * scale_)));
  };
  for (const auto& p : s.people) cv::circle(img, pixel(p), radius(s.person_radius), kPerson, 2);
  cv::polylines(img, true_path_, false, kTrue, 2);
  if (!estimated_path_.empty()) cv::polylines(img, estimated_path_, false, kEstimated, 1);
  const cv::Point c = pixel(s.robot.head<2>());
  cv::circle(img, c, radius(s.robot_radius), kTrue, 2);
  cv::line(img, c,
           pixel(s.robot.head<2>() +
                 s.robot_radius * Eigen::Vector2d(std::cos(s.robot.z()), std::sin(s.robot.z()))),
           kTrue, 2);
  if (s.goal < goals_.size()) cv::line(img, c, pixel(goals_[s.goal]), {200, 200, 200}, 1);
  char text[96];
  std::snprintf(text, sizeof text, "t %.1f s  goal %zu/%zu", s.t,
                std::min(s.goal + 1, goals_.size()), goals_.size());
  cv::putText(img, text, {10, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.7, kGoal, 2);
  video_.write(img);
}

void TopView::writeSummary(const std::string& png, const std::vector<bool>& reached) const {
  cv::Mat img = base_.clone();
  for (const auto& path : people_paths_) cv::polylines(img, path, false, kObstacle, 1);
  for (std::size_t i = 0; i < goals_.size() && i < reached.size(); ++i)
    cv::circle(img, pixel(goals_[i]), 12, reached[i] ? kTrue : kPerson, 2);
  cv::polylines(img, true_path_, false, kTrue, 2);
  if (!estimated_path_.empty()) cv::polylines(img, estimated_path_, false, kEstimated, 1);
  cv::putText(img, "true path", {10, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kTrue, 2);
  cv::putText(img, "estimated path", {10, 46}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kEstimated, 2);
  cv::putText(img, "people", {10, 68}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kPerson, 2);
  if (!cv::imwrite(png, img)) throw std::runtime_error("cannot write '" + png + "'");
}

}  // namespace dynslam::navdemo
