#pragma once
// Sparse feature tracking (method.md section 3, as VINS-Fusion's feature tracker does it):
// Shi-Tomasi corners spread over a grid with a minimum spacing, pyramidal KLT optical flow
// whose search starts where the gyro's rotation (infinite homography) or else the point's own
// previous motion puts it, a forward-backward check, RANSAC on the fundamental matrix for the
// static candidates, and the depth image's value at each corner. Ids are stable while a corner
// is tracked and never reused. OpenCV and Eigen only.
#include <dynslam/core/Frame.h>
#include <dynslam/frontend/GridCornerDetector.h>
#include <dynslam/frontend/OcclusionEdge.h>

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace dynslam::frontend {

/// Where the KLT search of each point starts.
enum class FlowInit {
  Gyro,            ///< the gyro's rotation over the interval (K R K^-1); previous motion without
  PreviousMotion,  ///< the point's displacement in the previous interval (constant velocity)
  None,            ///< the point's previous pixel (plain pyramidal KLT)
};

/// "gyro", "previous_motion", "none".
std::string toString(FlowInit init);

/// Which tracks the KLT residual gate judges.
enum class ResidualGateRegion {
  Everywhere,   ///< every track
  NearNonRigid  ///< tracks outside every object mask, within the margin of a non-rigid one's box
};

/// [FeatureTracking]'s settings. Keys, ranges, meanings: describe() in FeatureTrackingStage.cpp;
/// docs/parameters.md; why the departures from the method, with their measured gains:
/// docs/design.md, docs/notes/frontend.md (2026-11-28, front-end settings' history).
struct FeatureTrackerParams {
  int max_features = 300;
  GridCornerParams corners;
  int klt_window_px = 11;
  int klt_pyramid_levels = 3;
  /// The prediction (gyro or previous motion) leaves only the parallax and the objects' own
  /// motion to find, so fewer levels do. The backward pass of the forward-backward check starts
  /// at the point's previous pixel and uses the image alone.
  int klt_predicted_levels = 2;
  double max_fb_error_px = 0.5;
  /// A background patch that a walking person's silhouette passes over slides with it and can
  /// still pass the forward-backward check; its residual gives it away. Relative to the
  /// frame's median, so it follows the images' noise and contrast.
  double max_klt_residual_ratio = 3;
  /// Near non-rigid objects only: elsewhere the gate also drops good tracks whose appearance
  /// changes with the viewpoint, and tracks on the objects are the classification's to judge.
  ResidualGateRegion residual_gate_region = ResidualGateRegion::NearNonRigid;
  double residual_gate_margin_px = 20;
  OcclusionEdgeParams occlusion_edge{11};  ///< OcclusionEdge.h
  /// Only an object mask's readings are the nearer surface: the silhouettes that move. Static
  /// edges shift their T-junctions by parallax only, and their corners are many of a static
  /// room's.
  bool occlusion_edge_objects_only = true;
  /// As a track moves by a fraction of a pixel its reading next to a depth edge can switch
  /// surfaces: the estimator leaves such readings out (Feature::depth_at_edge).
  int depth_edge_radius_px = 5;
  FlowInit flow_init = FlowInit::Gyro;
  bool fundamental_ransac = true;
  /// Looser than VINS-Fusion's (~1.2 px at this focal length): tighter rejects many good tracks
  /// of a static room; 1.5 still drops a patch moving 8 px per frame against the camera's
  /// epipolar geometry (FeatureTrackerSimTest), i.e. a person the masks missed.
  double fundamental_threshold_px = 1.5;
  double fundamental_confidence = 0.99;
};

/// What happened to the features in one call, for logs, tests and the bench.
struct FeatureTrackerStats {
  int incoming = 0;        ///< features of the previous frame
  int lost_klt = 0;        ///< KLT found no match or the point left the image
  int lost_fb = 0;         ///< forward-backward mismatch
  int lost_residual = 0;   ///< KLT residual above max_klt_residual_ratio x the median
  int lost_ransac = 0;     ///< off the epipolar geometry of the static candidates
  int lost_occlusion = 0;  ///< just behind an occluding edge (occlusion_edge_radius_px)
  int pruned = 0;          ///< closer than min_distance_px to a longer track
  int tracked = 0;         ///< continued tracks in the output
  int detected = 0;        ///< new corners in the output
  bool gyro_used = false;  ///< the initial flow came from the gyro
  /// Medians over the continued tracks: KLT's residual (mean absolute grey difference over the
  /// window) and the distance from the initial guess to where KLT converged, pixels.
  double median_klt_residual = 0;
  double median_init_offset_px = 0;
  /// Wall time of the parts, ms: grey image + pyramid, KLT both ways, fundamental RANSAC,
  /// spacing + new corners.
  double ms_pyramid = 0, ms_klt = 0, ms_ransac = 0, ms_detect = 0;
  int cells_computed = 0;  ///< grid cells whose Shi-Tomasi corners were computed
};

class FeatureTracker {
 public:
  /// Throws std::invalid_argument naming a parameter that breaks a rule between keys (window
  /// odd, levels within the pyramid, residual ratio 0 or >= 1); the ranges of single keys are
  /// checked where the options are read (FeatureTrackingOptions).
  explicit FeatureTracker(FeatureTrackerParams params = {});

  /// Tracks the previous frame's features into `frame` (its colour image, intrinsics, IMU
  /// samples, extrinsics, depth and object masks) and tops them up with new corners. Features
  /// come out static with object_id -1: classification is a later stage's. Throws
  /// std::invalid_argument when the frame has no colour image.
  std::vector<core::Feature> track(const core::Frame& frame);

  const FeatureTrackerStats& lastStats() const { return stats_; }
  const FeatureTrackerParams& params() const { return params_; }
  /// Forgets every track (a gap in the stream); ids keep counting.
  void reset();

 private:
  struct Track {
    std::int64_t id;
    cv::Point2f pixel;
    cv::Point2f velocity;  ///< px per frame over the last interval
    int length;
  };
  /// The KLT start of each point; `predicted` says whether it is a prediction.
  std::vector<cv::Point2f> initialGuesses(const core::Frame& frame,
                                          const std::vector<cv::Point2f>& previous,
                                          bool& predicted);
  struct KltMatches;  // FeatureTracker.cpp
  /// KLT, forward-backward check, residual gate and fundamental-matrix RANSAC on tracks_.
  void trackExisting(const core::Frame& frame);
  /// KLT from the previous frame into this one and back (the KLT time in stats_).
  KltMatches kltBothWays(const core::Frame& frame);
  /// The matched tracks the residual gate keeps, moved to this frame, with their previous pixels.
  void passResidualGate(const core::Frame& frame, const KltMatches& m,
                        std::vector<Track>& survivors, std::vector<cv::Point2f>& survivorsPrevious);
  /// The residual above which a forward-backward survivor is dropped (infinity: no gate).
  double residualLimit(const std::vector<float>& residual,
                       const std::vector<size_t>& matched) const;
  /// For near_nonrigid: the boxes of the non-rigid objects' masks, grown by the margin.
  std::vector<cv::Rect> residualGateBoxes(const core::Frame& frame) const;
  void rejectByFundamental(const core::Frame& frame, const std::vector<cv::Point2f>& previous,
                           std::vector<Track>& tracks);
  /// Whether a pixel of `frame` is just behind an occluding edge (occlusion_edge; empty: off).
  std::function<bool(const cv::Point2f&)> occlusionEdgeTest(const core::Frame& frame) const;
  /// Drops the tracks at the pixels `where` says; how many.
  int dropTracks(const std::function<bool(const cv::Point2f&)>& where);
  /// Spacing among the tracks, then new corners where `rejected` (optional) does not say no.
  void pruneAndDetect(const cv::Mat& gray, const std::function<bool(const cv::Point2f&)>& rejected);

  FeatureTrackerParams params_;
  FeatureTrackerStats stats_;
  std::vector<Track> tracks_;
  std::vector<cv::Mat> previous_pyramid_, pyramid_;
  double previous_t_ = 0;
  std::int64_t next_id_ = 0;
  cv::Point2f median_velocity_{0, 0};  ///< of the last interval's tracks, for new corners
};

}  // namespace dynslam::frontend
