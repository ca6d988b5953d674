#include "ClassifierScene.h"

#include <opencv2/imgproc.hpp>

#include <optional>
#include <random>

namespace dynslam::frontend::testing {

const core::CameraIntrinsics kCamera{500, 500, 320, 240, 640, 480};

Eigen::Isometry3d cameraPose(double t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(kYawRate * t, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.3 * t, 0, 0);
  return T;
}

Scene::Scene() {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 150; ++i) background.emplace_back(4 * u(rng), 2 * u(rng), 6 + u(rng));
  auto box = [&](Eigen::Vector3d c, Eigen::Vector3d half, int n) {
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < n; ++i)
      pts.push_back(c + Eigen::Vector3d(half.x() * u(rng), half.y() * u(rng), half.z() * u(rng)));
    return pts;
  };
  objects.push_back({1,
                     core::MotionModel::NonRigid,
                     {0.8, 0, 0.3},  // walking person
                     box({-1.2, 0, 3.0}, {0.2, 0.5, 0.1}, 25)});
  objects.push_back({2,
                     core::MotionModel::NonRigid,
                     {0, 0, 0},  // standing person
                     box({0.9, 0, 3.5}, {0.2, 0.5, 0.1}, 25)});
  objects.push_back({3,
                     core::MotionModel::Rigid,
                     {0, 0, 0},  // parked car
                     box({-0.3, 0.8, 4.5}, {0.6, 0.25, 0.3}, 25)});
  objects.push_back({4,
                     core::MotionModel::Rigid,
                     {0, 0, -1.5},  // driving car
                     box({2.2, 0.5, 5.0}, {0.5, 0.3, 0.3}, 25)});
}

core::Frame Scene::frame(int k) const {
  core::Frame f;
  f.index = size_t(k);
  f.t = k * kDt;
  f.intrinsics = kCamera;
  for (int s = 1; s <= 7; ++s) {
    core::ImuSample imu;
    imu.t = f.t - kDt + s * kDt / 7;
    imu.gyro = Eigen::Vector3d(0, kYawRate, 0);
    imu.has_gyro = true;
    f.imu.push_back(imu);
  }
  const Eigen::Isometry3d T_c_w = cameraPose(f.t).inverse();
  auto project = [&](const Eigen::Vector3d& X, std::int64_t id) -> std::optional<cv::Point2f> {
    const Eigen::Vector3d P = T_c_w * X;
    const cv::Point2f px(float(kCamera.fx * P.x() / P.z() + kCamera.cx),
                         float(kCamera.fy * P.y() / P.z() + kCamera.cy));
    if (P.z() < 0.5 || px.x < 0 || px.y < 0 || px.x > 639 || px.y > 479) return std::nullopt;
    core::Feature feat;
    feat.id = id;
    feat.pixel = px;
    feat.depth = float(P.z());
    f.features.push_back(feat);
    return px;
  };
  std::vector<cv::Rect> boxes;
  for (size_t j = 0; j < objects.size(); ++j) {
    const auto& o = objects[j];
    std::vector<cv::Point2f> px;
    for (size_t i = 0; i < o.points.size(); ++i)
      if (auto p = project(o.points[i] + o.velocity * f.t, 1000 * std::int64_t(j + 1) + i))
        px.push_back(*p);
    cv::Rect box = cv::boundingRect(px);
    box = cv::Rect(box.x - 3, box.y - 3, box.width + 6, box.height + 6) & cv::Rect(0, 0, 640, 480);
    boxes.push_back(box);
    core::Track track;
    track.id = o.track_id;
    track.model = o.model;
    track.state = core::TrackState::Confirmed;
    f.tracks.push_back(track);
    core::ObjectMask m;
    m.track = int(j);
    m.roi = box;
    m.mask = cv::Mat(box.size(), CV_8UC1, cv::Scalar(255));
    m.d_t = (T_c_w * (o.points[0] + o.velocity * f.t)).z();
    m.valid = true;
    f.object_masks.push_back(m);
  }
  // Background features hidden by (or inside the box of) an object are not seen.
  for (size_t i = 0; i < background.size(); ++i) {
    const Eigen::Vector3d P = T_c_w * background[i];
    const cv::Point2f px(float(kCamera.fx * P.x() / P.z() + kCamera.cx),
                         float(kCamera.fy * P.y() / P.z() + kCamera.cy));
    bool hidden = false;
    for (const auto& b : boxes) hidden |= b.contains(cv::Point(int(px.x + 0.5f), int(px.y + 0.5f)));
    if (!hidden) project(background[i], std::int64_t(i));
  }
  return f;
}

}  // namespace dynslam::frontend::testing
