#include "dynslam/frontend/FeatureTracker.h"

#include "dynslam/frontend/CameraMotion.h"
#include "dynslam/frontend/FlowPrediction.h"
#include "dynslam/frontend/OcclusionEdge.h"

#include <dynslam/core/Median.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace dynslam::frontend {
namespace {

void require(bool ok, const std::string& key, double value, const char* rule) {
  if (!ok) throw std::invalid_argument(key + " = " + std::to_string(value) + ": must be " + rule);
}

/// The rules a key's range cannot state (the ranges are FeatureTrackingOptions::describe()'s).
void checkRulesBetweenKeys(const FeatureTrackerParams& p) {
  require(p.klt_window_px % 2 == 1, "klt_window_px", p.klt_window_px, "odd");
  require(p.klt_predicted_levels <= p.klt_pyramid_levels, "klt_predicted_levels",
          p.klt_predicted_levels, "<= klt_pyramid_levels");
  require(p.corners.level <= p.klt_pyramid_levels, "corner_level", p.corners.level,
          "<= klt_pyramid_levels (a level of the KLT pyramid)");
  require(p.max_klt_residual_ratio == 0 || p.max_klt_residual_ratio >= 1, "max_klt_residual_ratio",
          p.max_klt_residual_ratio, "0 (off) or >= 1");
}

/// KLT's termination, per pyramid level: OpenCV's and VINS-Fusion's 30 iterations or an update
/// under 0.01 px (0.001 px changed nothing: docs/notes/estimator.md).
constexpr int kKltMaxIterations = 30;
constexpr double kKltEpsilonPx = 0.01;

/// KLT needs the whole window inside the image to trust a match (VINS-Fusion keeps 1 px).
bool insideImage(const cv::Point2f& p, cv::Size size) {
  return p.x >= 1 && p.y >= 1 && p.x < size.width - 1 && p.y < size.height - 1;
}

bool insideAnyObjectMask(const core::Frame& frame, const cv::Point2f& p) {
  const cv::Point q(cvRound(p.x), cvRound(p.y));
  for (const auto& m : frame.object_masks)
    if (!m.mask.empty() && m.roi.contains(q) && m.mask.at<uint8_t>(q - m.roi.tl()) != 0)
      return true;
  return false;
}

float depthAt(const cv::Mat& depth, const cv::Point2f& p) {
  const int r = cvRound(p.y), c = cvRound(p.x);
  if (depth.empty() || r < 0 || c < 0 || r >= depth.rows || c >= depth.cols) return 0;
  const float z = depth.at<float>(r, c);
  return std::isfinite(z) && z > 0 ? z : 0;
}

/// Adds the lifetime of the scope to `ms`.
class ScopedMs {
 public:
  explicit ScopedMs(double& ms) : ms_(ms), start_(std::chrono::steady_clock::now()) {}
  ~ScopedMs() {
    ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
               .count();
  }

 private:
  double& ms_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

std::string toString(FlowInit init) {
  switch (init) {
    case FlowInit::Gyro:
      return "gyro";
    case FlowInit::PreviousMotion:
      return "previous_motion";
    case FlowInit::None:
      return "none";
  }
  return "?";
}

FeatureTracker::FeatureTracker(FeatureTrackerParams params) : params_(params) {
  checkRulesBetweenKeys(params_);
}

void FeatureTracker::reset() {
  tracks_.clear();
  previous_pyramid_.clear();
  median_velocity_ = {0, 0};
}

std::vector<core::Feature> FeatureTracker::track(const core::Frame& frame) {
  if (frame.rgb.empty())
    throw std::invalid_argument("frame " + std::to_string(frame.index) +
                                ": no colour image to track features in");
  if (!frame.depth.empty() && frame.depth.type() != CV_32FC1)
    throw std::invalid_argument("frame " + std::to_string(frame.index) +
                                ": depth must be CV_32FC1 metres");
  stats_ = {};
  cv::Mat gray;
  {
    ScopedMs timer(stats_.ms_pyramid);
    if (frame.rgb.channels() == 3)
      cv::cvtColor(frame.rgb, gray, cv::COLOR_BGR2GRAY);
    else
      gray = frame.rgb;
    // One pyramid (with derivatives) per image, used by the forward pass into it, the backward
    // pass out of it, and the next frame's forward pass.
    const cv::Size window(params_.klt_window_px, params_.klt_window_px);
    cv::buildOpticalFlowPyramid(gray, pyramid_, window, params_.klt_pyramid_levels, true);
  }

  if (!previous_pyramid_.empty() && previous_pyramid_[0].size() == gray.size())
    trackExisting(frame);
  else
    tracks_.clear();
  const auto behindEdge = occlusionEdgeTest(frame);
  if (behindEdge) stats_.lost_occlusion = dropTracks(behindEdge);
  {
    ScopedMs timer(stats_.ms_detect);
    pruneAndDetect(gray, behindEdge);  // new corners are not placed there either
  }

  OcclusionEdgeParams depthEdge = params_.occlusion_edge;  // its gap, this radius
  depthEdge.radius_px = params_.depth_edge_radius_px;
  std::vector<core::Feature> out;
  out.reserve(tracks_.size());
  // Track::velocity is px per frame interval; features carry px/s.
  const double interval = frame.t - previous_t_;
  const float perSecond = interval > 0 && interval < 1.0 ? float(1.0 / interval) : 0.f;
  for (const auto& t : tracks_) {
    core::Feature f;
    f.id = t.id;
    f.pixel = t.pixel;
    f.depth = depthAt(frame.depth, t.pixel);
    f.depth_at_edge = nearDepthEdge(frame.depth, t.pixel, depthEdge);  // radius 0: false
    f.track_length = t.length;
    f.velocity = t.velocity * perSecond;
    out.push_back(f);
  }
  std::swap(previous_pyramid_, pyramid_);
  previous_t_ = frame.t;
  return out;
}

std::vector<cv::Point2f> FeatureTracker::initialGuesses(const core::Frame& frame,
                                                        const std::vector<cv::Point2f>& previous,
                                                        bool& predicted) {
  predicted = params_.flow_init != FlowInit::None;
  if (!predicted) return previous;
  if (params_.flow_init == FlowInit::Gyro && frame.intrinsics.fx > 0 && frame.intrinsics.fy > 0) {
    if (const auto R = gyroCameraRotation(frame.imu, previous_t_, frame.t, frame.T_body_imu,
                                          frame.T_body_camera)) {
      stats_.gyro_used = true;
      return predictByRotation(previous, frame.intrinsics, *R);
    }
  }
  std::vector<cv::Point2f> guesses(previous.size());
  for (size_t i = 0; i < previous.size(); ++i) guesses[i] = previous[i] + tracks_[i].velocity;
  return guesses;
}

/// The previous frame's tracks after KLT both ways (FeatureTracker::kltBothWays).
struct FeatureTracker::KltMatches {
  std::vector<cv::Point2f> previous;  ///< each track's pixel in the previous frame
  std::vector<cv::Point2f> guesses;   ///< where KLT started
  std::vector<cv::Point2f> current;   ///< where KLT converged
  std::vector<float> residual;        ///< KLT's, per track
  std::vector<size_t> matched;        ///< the tracks that passed the forward-backward check
};

void FeatureTracker::trackExisting(const core::Frame& frame) {
  stats_.incoming = int(tracks_.size());
  if (tracks_.empty()) return;
  const KltMatches m = kltBothWays(frame);
  std::vector<Track> survivors;
  std::vector<cv::Point2f> survivorsPrevious;
  passResidualGate(frame, m, survivors, survivorsPrevious);
  if (params_.fundamental_ransac) {
    ScopedMs timer(stats_.ms_ransac);
    rejectByFundamental(frame, survivorsPrevious, survivors);
  }
  tracks_ = std::move(survivors);
  if (!tracks_.empty()) {
    std::vector<double> vx, vy;
    for (const auto& t : tracks_) {
      vx.push_back(t.velocity.x);
      vy.push_back(t.velocity.y);
    }
    median_velocity_ = cv::Point2f(float(core::upperMedian(vx)), float(core::upperMedian(vy)));
  }
}

FeatureTracker::KltMatches FeatureTracker::kltBothWays(const core::Frame& frame) {
  const cv::Size size = frame.rgb.size();
  const cv::Size window(params_.klt_window_px, params_.klt_window_px);
  const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, kKltMaxIterations,
                              kKltEpsilonPx);
  KltMatches m;
  m.previous.resize(tracks_.size());
  for (size_t i = 0; i < tracks_.size(); ++i) m.previous[i] = tracks_[i].pixel;
  bool predicted = false;
  m.guesses = initialGuesses(frame, m.previous, predicted);
  m.current = m.guesses;
  std::vector<uchar> status;
  std::optional<ScopedMs> kltTimer(stats_.ms_klt);
  cv::calcOpticalFlowPyrLK(previous_pyramid_, pyramid_, m.previous, m.current, status, m.residual,
                           window,
                           predicted ? params_.klt_predicted_levels : params_.klt_pyramid_levels,
                           stop, cv::OPTFLOW_USE_INITIAL_FLOW);

  // Forward-backward check on the forward survivors only: track them back, starting from
  // where they came from, and keep those that land within max_fb_error_px of it. Starting at
  // the answer, the full-resolution level alone settles it (VINS-Fusion adds one level; a
  // wrong forward match drifts away from the start either way).
  std::vector<size_t> forward;
  std::vector<cv::Point2f> there, back;
  for (size_t i = 0; i < tracks_.size(); ++i) {
    if (!status[i] || !insideImage(m.current[i], size)) {
      ++stats_.lost_klt;
      continue;
    }
    forward.push_back(i);
    there.push_back(m.current[i]);
    back.push_back(m.previous[i]);
  }
  std::vector<uchar> backStatus;
  std::vector<float> backResidual;
  if (!forward.empty())
    cv::calcOpticalFlowPyrLK(pyramid_, previous_pyramid_, there, back, backStatus, backResidual,
                             window, 0, stop, cv::OPTFLOW_USE_INITIAL_FLOW);
  kltTimer.reset();

  const double maxFb2 = params_.max_fb_error_px * params_.max_fb_error_px;
  for (size_t k = 0; k < forward.size(); ++k) {
    const cv::Point2f d = back[k] - m.previous[forward[k]];
    if (!backStatus[k] || d.dot(d) > maxFb2) {
      ++stats_.lost_fb;
      continue;
    }
    m.matched.push_back(forward[k]);
  }
  return m;
}

void FeatureTracker::passResidualGate(const core::Frame& frame, const KltMatches& m,
                                      std::vector<Track>& survivors,
                                      std::vector<cv::Point2f>& survivorsPrevious) {
  const double maxResidual = residualLimit(m.residual, m.matched);
  const std::vector<cv::Rect> gateBoxes = residualGateBoxes(frame);
  const auto gated = [&](size_t i) {
    if (m.residual[i] <= maxResidual) return false;
    if (params_.residual_gate_region == ResidualGateRegion::Everywhere) return true;
    // Tracks on the objects are the classification's to judge (dropping them cost recall).
    if (insideAnyObjectMask(frame, m.current[i])) return false;
    const cv::Point from(cvRound(m.previous[i].x), cvRound(m.previous[i].y));
    const cv::Point to(cvRound(m.current[i].x), cvRound(m.current[i].y));
    return std::any_of(gateBoxes.begin(), gateBoxes.end(),
                       [&](const cv::Rect& b) { return b.contains(from) || b.contains(to); });
  };
  std::vector<double> residuals, offsets;
  for (const size_t i : m.matched) {
    if (gated(i)) {
      ++stats_.lost_residual;
      continue;
    }
    Track t = tracks_[i];
    t.velocity = m.current[i] - m.previous[i];
    t.pixel = m.current[i];
    ++t.length;
    survivors.push_back(t);
    survivorsPrevious.push_back(m.previous[i]);
    residuals.push_back(m.residual[i]);
    offsets.push_back(cv::norm(m.current[i] - m.guesses[i]));
  }
  stats_.median_klt_residual = core::upperMedian(residuals);
  stats_.median_init_offset_px = core::upperMedian(offsets);
}

double FeatureTracker::residualLimit(const std::vector<float>& residual,
                                     const std::vector<size_t>& matched) const {
  if (params_.max_klt_residual_ratio <= 0 || matched.empty())
    return std::numeric_limits<double>::infinity();
  std::vector<double> r;
  r.reserve(matched.size());
  for (const size_t i : matched) r.push_back(residual[i]);
  return params_.max_klt_residual_ratio * core::upperMedian(r);
}

std::vector<cv::Rect> FeatureTracker::residualGateBoxes(const core::Frame& frame) const {
  std::vector<cv::Rect> boxes;
  if (params_.residual_gate_region != ResidualGateRegion::NearNonRigid) return boxes;
  const int margin = int(std::ceil(params_.residual_gate_margin_px));
  for (const auto& m : frame.object_masks) {
    // The model of the mask's detection, or of its track when it segments a predicted box.
    const core::MotionModel* model = nullptr;
    if (m.detection >= 0 && m.detection < int(frame.detections.size()))
      model = &frame.detections[size_t(m.detection)].model;
    else if (m.track >= 0 && m.track < int(frame.tracks.size()))
      model = &frame.tracks[size_t(m.track)].model;
    if (!model || *model != core::MotionModel::NonRigid) continue;
    boxes.emplace_back(m.roi.x - margin, m.roi.y - margin, m.roi.width + 2 * margin,
                       m.roi.height + 2 * margin);
  }
  return boxes;
}

void FeatureTracker::rejectByFundamental(const core::Frame& frame,
                                         const std::vector<cv::Point2f>& previous,
                                         std::vector<Track>& tracks) {
  // Only the static candidates (outside every object mask) must share the camera's epipolar
  // geometry; features on objects move on their own and are judged by the classification.
  std::vector<size_t> candidates;
  std::vector<cv::Point2f> from, to;
  for (size_t i = 0; i < tracks.size(); ++i) {
    if (insideAnyObjectMask(frame, tracks[i].pixel)) continue;
    candidates.push_back(i);
    from.push_back(previous[i]);
    to.push_back(tracks[i].pixel);
  }
  if (candidates.size() < 8) return;  // the 8-point minimum of findFundamentalMat
  std::vector<uchar> inlier;
  const cv::Mat F =
      cv::findFundamentalMat(from, to, cv::FM_RANSAC, params_.fundamental_threshold_px,
                             params_.fundamental_confidence, inlier);
  if (F.empty() || inlier.size() != candidates.size()) return;  // degenerate: keep them all
  std::vector<bool> drop(tracks.size(), false);
  for (size_t k = 0; k < candidates.size(); ++k)
    if (!inlier[k]) {
      drop[candidates[k]] = true;
      ++stats_.lost_ransac;
    }
  size_t w = 0;
  for (size_t i = 0; i < tracks.size(); ++i)
    if (!drop[i]) tracks[w++] = tracks[i];
  tracks.resize(w);
}

std::function<bool(const cv::Point2f&)> FeatureTracker::occlusionEdgeTest(
    const core::Frame& frame) const {
  if (params_.occlusion_edge.radius_px <= 0 || frame.depth.empty()) return {};
  if (params_.occlusion_edge_objects_only && frame.object_masks.empty()) return {};
  cv::Mat nearer;  // empty: every reading may be the nearer surface
  if (params_.occlusion_edge_objects_only) {
    nearer = cv::Mat::zeros(frame.depth.size(), CV_8UC1);
    const cv::Rect image({0, 0}, nearer.size());
    for (const auto& m : frame.object_masks) {
      const cv::Rect roi = m.roi & image;
      if (m.mask.empty() || roi.empty()) continue;
      cv::Mat dst = nearer(roi);
      cv::bitwise_or(dst, m.mask(roi - m.roi.tl()), dst);
    }
  }
  return [depth = frame.depth, nearer, &p = params_.occlusion_edge](const cv::Point2f& pixel) {
    return behindOcclusionEdge(depth, pixel, p, nearer);
  };
}

int FeatureTracker::dropTracks(const std::function<bool(const cv::Point2f&)>& where) {
  const auto end = std::remove_if(tracks_.begin(), tracks_.end(),
                                  [&](const Track& t) { return where(t.pixel); });
  const int dropped = int(tracks_.end() - end);
  tracks_.erase(end, tracks_.end());
  return dropped;
}

void FeatureTracker::pruneAndDetect(const cv::Mat& gray,
                                    const std::function<bool(const cv::Point2f&)>& rejected) {
  // Longest tracks claim their space first; a younger track that drifted into it goes.
  std::vector<size_t> order(tracks_.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return tracks_[a].length > tracks_[b].length; });
  cv::Mat free = freeSpaceMask(gray.size(), {}, params_.corners);
  std::vector<bool> keep(tracks_.size(), false);
  for (size_t i : order) keep[i] = claimIfFree(free, tracks_[i].pixel, params_.corners);
  std::vector<Track> kept;
  std::vector<cv::Point2f> occupied;
  for (size_t i = 0; i < tracks_.size(); ++i) {
    if (!keep[i]) {
      ++stats_.pruned;
      continue;
    }
    kept.push_back(tracks_[i]);
    occupied.push_back(tracks_[i].pixel);
  }
  tracks_ = std::move(kept);
  if (int(tracks_.size()) > params_.max_features) tracks_.resize(size_t(params_.max_features));
  stats_.tracked = int(tracks_.size());

  const int wanted = params_.max_features - int(tracks_.size());
  // buildOpticalFlowPyramid with derivatives interleaves image and derivative levels.
  const size_t step = pyramid_.size() > size_t(params_.klt_pyramid_levels) + 1 ? 2 : 1;
  const cv::Mat& scored =
      params_.corners.level == 0 ? gray : pyramid_.at(step * size_t(params_.corners.level));
  for (const auto& p : detectGridCorners(scored, free, occupied, wanted, params_.corners,
                                         &stats_.cells_computed, rejected))
    tracks_.push_back({next_id_++, p, median_velocity_, 1});
  stats_.detected = int(tracks_.size()) - stats_.tracked;
}

}  // namespace dynslam::frontend
