#include "dynslam/odometry/RgbdOdometryStage.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <optional>

namespace dynslam::odometry {
namespace {

cv::Mat toCv(const Eigen::Isometry3d& T) {
  cv::Mat m(4, 4, CV_64FC1);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m.at<double>(r, c) = T.matrix()(r, c);
  return m;
}

/// The rigid motion in a 4x4 CV_64F matrix, or nullopt when its rotation is not one: OpenCV
/// can return a diverged, non-orthonormal matrix even when it reports success, and one such
/// matrix poisons every later pose (Isometry3d::inverse assumes orthonormality).
std::optional<Eigen::Isometry3d> rigidMotion(const cv::Mat& m) {
  if (m.rows != 4 || m.cols != 4 || m.type() != CV_64FC1) return std::nullopt;
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) M(r, c) = m.at<double>(r, c);
  const Eigen::Matrix3d R = M.topLeftCorner<3, 3>();
  if (!M.allFinite() || (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-3 ||
      R.determinant() < 0)
    return std::nullopt;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  T.translation() = M.topRightCorner<3, 1>();
  return T;
}

double rotationDeg(const Eigen::Isometry3d& T) {
  return Eigen::AngleAxisd(T.rotation()).angle() * 180.0 / M_PI;
}

// The frame's grey image; a black one for method icp, which works on depth alone.
cv::Mat greyOf(const core::Frame& frame, const std::string& method) {
  cv::Mat grey;
  if (!frame.rgb.empty())
    cv::cvtColor(frame.rgb, grey, cv::COLOR_BGR2GRAY);
  else if (method != "icp")
    throw std::runtime_error("RgbdOdometry: frame " + std::to_string(frame.index) +
                             " has no colour image; method = icp works on depth alone");
  else
    grey = cv::Mat(frame.depth.size(), CV_8UC1, cv::Scalar(0));
  return grey;
}

}  // namespace

void RgbdOdometryOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  v.word("method", method, {"rgbd_icp", "rgbd", "icp"},
         "rgbd_icp: photometric and geometric | rgbd: photometric | icp: geometric (depth alone)");
  v.key("min_depth", min_depth, Range::atLeast(0), "m; nearer pixels are not used");
  v.key("max_depth", max_depth, Range::above(0), "m; farther pixels are not used");
  v.key("keyframe_translation", keyframe_translation, Range::atLeast(0),
        "m from the keyframe that starts a new one");
  v.key("keyframe_rotation_deg", keyframe_rotation_deg, Range::atLeast(0),
        "deg from the keyframe that starts a new one");
  v.key("max_translation", max_translation, Range::above(0),
        "m; a larger estimated motion is a failure");
  v.key("max_rotation_deg", max_rotation_deg, Range::above(0),
        "deg; a larger estimated motion is a failure");
}

struct RgbdOdometryStage::Impl {
  cv::Ptr<cv::rgbd::Odometry> odometry;
  cv::Ptr<cv::rgbd::OdometryFrame> keyframe;
  Eigen::Isometry3d T_world_keyframe = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_keyframe_last = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_world_last = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d last_motion = Eigen::Isometry3d::Identity();  // previous -> current

  // A frame used as the source of compute() is not reusable as a destination (OpenCV keeps
  // source-only data in its cache), so a keyframe always gets a frame object of its own.
  cv::Ptr<cv::rgbd::OdometryFrame> makeKeyframe(const cv::Mat& grey, const cv::Mat& depth) const {
    auto kf = cv::rgbd::OdometryFrame::create(grey, depth);
    odometry->prepareFrameCache(kf, cv::rgbd::OdometryFrame::CACHE_DST);
    return kf;
  }

  // The motion keyframe <- current, aligned from `predicted`; nullopt when the alignment failed,
  // gave no rigid motion, or a step from the last frame larger than the options allow.
  std::optional<Eigen::Isometry3d> measure(const cv::Mat& grey, const cv::Mat& depth,
                                           const Eigen::Isometry3d& predicted,
                                           const RgbdOdometryOptions& o) {
    auto current = cv::rgbd::OdometryFrame::create(grey, depth);
    cv::Mat Rt;
    if (!odometry->compute(current, keyframe, Rt, toCv(predicted))) return std::nullopt;
    const auto measured = rigidMotion(Rt);
    if (!measured) return std::nullopt;
    const Eigen::Isometry3d step = T_keyframe_last.inverse() * *measured;
    if (step.translation().norm() > o.max_translation || rotationDeg(step) > o.max_rotation_deg)
      return std::nullopt;
    return measured;
  }
};

RgbdOdometryStage::RgbdOdometryStage() : impl_(std::make_unique<Impl>()) {}
RgbdOdometryStage::~RgbdOdometryStage() = default;

void RgbdOdometryStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
  const auto& o = options_;
  // The camera matrix is set from the first frame's intrinsics; the rejection of
  // correspondences more than 7 cm apart in depth and the share of pixels sampled (7 %) are
  // OpenCV's defaults.
  const cv::Mat noK;
  if (o.method == "rgbd_icp")
    impl_->odometry = cv::rgbd::RgbdICPOdometry::create(noK, o.min_depth, o.max_depth);
  else if (o.method == "rgbd")
    impl_->odometry = cv::rgbd::RgbdOdometry::create(noK, o.min_depth, o.max_depth);
  else  // icp (describe() admits no other word)
    impl_->odometry = cv::rgbd::ICPOdometry::create(noK, o.min_depth, o.max_depth);
}

void RgbdOdometryStage::process(core::Frame& frame) {
  auto& s = *impl_;
  if (frame.depth.empty())
    throw std::runtime_error("RgbdOdometry: frame " + std::to_string(frame.index) +
                             " has no depth");
  const cv::Mat grey = greyOf(frame, options_.method);
  if (!s.keyframe) {  // the first frame: the world's origin and the first keyframe
    const auto& k = frame.intrinsics;
    s.odometry->setCameraMatrix((cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1));
    s.keyframe = s.makeKeyframe(grey, frame.depth);
    ++keyframes_;
    ++frames_;
    frame.T_world_camera = Eigen::Isometry3d::Identity();
    return;
  }

  // Predict with constant velocity; it is the initial guess and the fallback on failure.
  const Eigen::Isometry3d predicted = s.T_keyframe_last * s.last_motion;
  const auto measured = s.measure(grey, frame.depth, predicted, options_);
  const bool ok = measured.has_value();
  const Eigen::Isometry3d T_keyframe_current = ok ? *measured : predicted;
  if (!ok) {
    ++failures_;
    MRPT_LOG_WARN_STREAM("frame " << frame.index << ": odometry failed; using the prediction");
  }

  const Eigen::Isometry3d T_world_current = s.T_world_keyframe * T_keyframe_current;
  // After a failure the motion is unknown: extrapolating the guess again would compound it.
  s.last_motion = ok ? s.T_world_last.inverse() * T_world_current : Eigen::Isometry3d::Identity();
  s.T_world_last = T_world_current;
  s.T_keyframe_last = T_keyframe_current;
  if (!ok || T_keyframe_current.translation().norm() > options_.keyframe_translation ||
      rotationDeg(T_keyframe_current) > options_.keyframe_rotation_deg) {
    s.keyframe = s.makeKeyframe(grey, frame.depth);
    s.T_world_keyframe = T_world_current;
    s.T_keyframe_last = Eigen::Isometry3d::Identity();
    ++keyframes_;
  }
  ++frames_;
  frame.T_world_camera = T_world_current;
}

void RgbdOdometryStage::finish() {
  MRPT_LOG_INFO_STREAM(frames_ << " frames, " << keyframes_ << " keyframes, " << failures_
                               << " failures");
}

}  // namespace dynslam::odometry
