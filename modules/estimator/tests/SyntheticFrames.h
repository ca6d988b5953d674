#pragma once
// Frames for EstimatorStage tests, made without images: the corner of the synthetic room
// (SyntheticRoom.h: back wall z = 3, floor y = 1, left wall x = -1.5; y points down, so gravity
// is +y) as static points, seen from a smooth handheld-like path as tracked features (pixel with
// noise, depth with the sensor's noise), together with the exact IMU samples of that path
// (200 Hz, no bias). Camera = body = IMU, and the path starts at the identity: the estimator's
// world (its first frame's body frame) is the truth's. Optionally a walker: points on a box
// crossing the view, on object 1, of a given feature class.
#include <dynslam/core/Frame.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace dynslam::estimator::testing {

/// The path: position a sum of sines, rotation about one fixed axis by a sine (so the body rate
/// is exact); about 0.4 m/s and 10 degrees, accelerations of ~0.5 m/s^2 (enough to initialize
/// the IMU). Pose at t = 0: the identity.
struct RoomPath {
  static Eigen::Vector3d position(double t) {
    return {0.3 * std::sin(1.2 * t), 0.08 * std::sin(1.7 * t), 0.25 * std::sin(0.9 * t)};
  }
  static Eigen::Vector3d velocity(double t) {
    return {0.36 * std::cos(1.2 * t), 0.136 * std::cos(1.7 * t), 0.225 * std::cos(0.9 * t)};
  }
  static Eigen::Vector3d acceleration(double t) {
    return {-0.432 * std::sin(1.2 * t), -0.2312 * std::sin(1.7 * t), -0.2025 * std::sin(0.9 * t)};
  }
  static Eigen::Vector3d axis() { return Eigen::Vector3d(0.2, 1.0, 0.1).normalized(); }
  static double angle(double t) { return 0.18 * std::sin(1.1 * t); }
  static double angleRate(double t) { return 0.198 * std::cos(1.1 * t); }

  static Eigen::Isometry3d pose(double t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(angle(t), axis()).toRotationMatrix();
    T.translation() = position(t);
    return T;
  }
  /// What the IMU measures at t: body rate and specific force (gravity (0, 9.81, 0) world).
  static core::ImuSample imuAt(double t) {
    core::ImuSample s;
    s.t = t;
    s.gyro = angleRate(t) * axis();
    s.acc = pose(t).linear().transpose() * (acceleration(t) - Eigen::Vector3d(0, 9.81, 0));
    s.has_gyro = s.has_acc = true;
    return s;
  }
};

/// A path along which the camera-IMU time offset and the extrinsic rotation are unobservable
/// after the first kStart s: no rotation at all, and a constant velocity once the start (one
/// period of a sine in the velocity, accelerations up to 0.8 m/s^2, enough to initialize the
/// IMU) is over.
struct StraightPath {
  static constexpr double kStart = 3.0;
  static Eigen::Vector3d cruise() { return {0.3, 0.0, 0.05}; }
  static Eigen::Vector3d swing() { return {0.3, 0.15, 0.25}; }
  static double phase(double t) { return 2 * M_PI * std::min(t, kStart) / kStart; }
  static Eigen::Isometry3d pose(double t) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = t * cruise() + kStart / (2 * M_PI) * (1 - std::cos(phase(t))) * swing();
    return T;
  }
  static core::ImuSample imuAt(double t) {
    core::ImuSample s;
    s.t = t;
    const double a = t < kStart ? 2 * M_PI / kStart * std::cos(phase(t)) : 0.0;
    s.acc = a * swing() - Eigen::Vector3d(0, 9.81, 0);
    s.has_gyro = s.has_acc = true;
    return s;
  }
};

struct SyntheticFramesOptions {
  double fps = 30;
  double imu_rate = 200;
  bool imu = true;           ///< frames carry IMU samples
  int points = 400;          ///< static points on the room's surfaces
  double pixel_noise = 0.3;  ///< px, Gaussian
  unsigned seed = 7;
  bool walker = false;  ///< points on a box walking across the view at 0.6 m/s
  core::FeatureClass walker_class = core::FeatureClass::NonRigid;
  /// s; the images are taken this long after their stamps (t_imu = t_camera + offset, the
  /// estimator's t_d); the features carry their image velocity over the last frame interval.
  double time_offset = 0;
  bool straight = false;  ///< StraightPath instead of RoomPath
};

class SyntheticFrames {
 public:
  static constexpr std::int64_t kWalkerFirstId = 100000;

  explicit SyntheticFrames(SyntheticFramesOptions options = {})
      : options_(options), rng_(options.seed), camera_(dynslam::testing::vgaCamera()) {
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < options_.points; ++i) {
      const double a = u(rng_), b = u(rng_), which = u(rng_);
      if (which < 0.6)  // back wall
        points_.emplace_back(-1.5 + 4.5 * a, -1.5 + 2.5 * b, 3.0);
      else if (which < 0.8)  // floor
        points_.emplace_back(-1.5 + 4.5 * a, 1.0, 1.0 + 2.0 * b);
      else  // left wall
        points_.emplace_back(-1.5, -1.5 + 2.5 * a, 1.0 + 2.0 * b);
    }
    for (int i = 0; i < 60; ++i)  // the walker, in its own frame (a 0.5 x 1.6 x 0.3 m box)
      walker_.emplace_back(0.5 * (u(rng_) - 0.5), 1.6 * (u(rng_) - 0.5), 0.3 * (u(rng_) - 0.5));
  }

  double time(std::size_t index) const { return double(index) / options_.fps; }
  /// The body pose at frame `index`'s stamp (on the IMU clock).
  Eigen::Isometry3d truth(std::size_t index) const { return poseAt(time(index)); }
  Eigen::Isometry3d poseAt(double t) const {
    return options_.straight ? StraightPath::pose(t) : RoomPath::pose(t);
  }

  /// Frame `index` (call in order: the noise comes from one stream), with the IMU samples since
  /// the previous frame and the features it sees.
  core::Frame frame(std::size_t index) {
    core::Frame f;
    f.index = index;
    f.t = time(index);
    f.intrinsics = camera_;
    if (options_.imu)  // the samples in (previous frame's t, t]
      for (long k = index == 0 ? 0 : lastSample(index - 1) + 1; k <= lastSample(index); ++k)
        f.imu.push_back(options_.straight ? StraightPath::imuAt(double(k) / options_.imu_rate)
                                          : RoomPath::imuAt(double(k) / options_.imu_rate));
    // Taken at t + offset; the velocity as a tracker measures it, from the frame before.
    const double taken = f.t + options_.time_offset;
    const Eigen::Isometry3d T_camera_world = poseAt(taken).inverse();
    const Eigen::Isometry3d T_previous_world = poseAt(taken - 1.0 / options_.fps).inverse();
    for (std::size_t i = 0; i < points_.size(); ++i)
      see(T_camera_world * points_[i], T_previous_world * points_[i], std::int64_t(i),
          core::FeatureClass::Static, -1, f);
    if (options_.walker) {
      const auto centre = [](double t) { return Eigen::Vector3d(-1.2 + 0.6 * t, 0.1, 2.0); };
      for (std::size_t i = 0; i < walker_.size(); ++i)
        see(T_camera_world * (centre(taken) + walker_[i]),
            T_previous_world * (centre(taken - 1.0 / options_.fps) + walker_[i]),
            kWalkerFirstId + std::int64_t(i), options_.walker_class, 1, f);
    }
    return f;
  }

 private:
  long lastSample(std::size_t index) const {
    return long(std::floor(time(index) * options_.imu_rate + 1e-9));
  }
  /// `p` in the camera now, `before` one frame interval earlier (the image velocity).
  void see(const Eigen::Vector3d& p, const Eigen::Vector3d& before, std::int64_t id,
           core::FeatureClass cls, int object, core::Frame& f) {
    if (p.z() < 0.3 || before.z() < 0.3) return;
    const double u = camera_.fx * p.x() / p.z() + camera_.cx;
    const double v = camera_.fy * p.y() / p.z() + camera_.cy;
    const double u0 = camera_.fx * before.x() / before.z() + camera_.cx;
    const double v0 = camera_.fy * before.y() / before.z() + camera_.cy;
    if (u < 0 || v < 0 || u >= camera_.width || v >= camera_.height) return;
    std::normal_distribution<double> pixel(0, options_.pixel_noise);
    std::normal_distribution<double> depth(0, 0.001 + 0.0015 * p.z() * p.z());
    core::Feature feature;
    feature.id = id;
    feature.pixel = cv::Point2f(float(u + pixel(rng_)), float(v + pixel(rng_)));
    feature.depth = float(p.z() + depth(rng_));
    feature.feature_class = cls;
    feature.object_id = object;
    feature.velocity = cv::Point2f(float((u - u0) * options_.fps), float((v - v0) * options_.fps));
    f.features.push_back(feature);
  }

  SyntheticFramesOptions options_;
  std::mt19937 rng_;
  core::CameraIntrinsics camera_;
  std::vector<Eigen::Vector3d> points_, walker_;
};

}  // namespace dynslam::estimator::testing
