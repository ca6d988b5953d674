#pragma once
// What the perception stages add to a Frame (method.md sections 1 and 2): detector boxes,
// depth-threshold instance masks and Kalman tracks. MRPT-free, like Frame.h.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <algorithm>
#include <string>

namespace dynslam::core {

/// min(a, b) / max(a, b) of two depths > 0: 1 when they agree, towards 0 as one is a multiple of
/// the other. The depth factor of method.md's depth IoU (section 2), and how the segmentation and
/// the tracker tell which of two depths is nearer an expected one.
inline double depthRatio(double a, double b) { return std::min(a, b) / std::max(a, b); }

/// How the method models an object's motion (method.md section 1: person non-rigid, car rigid
/// by default; the detector's class map in the ini decides per class).
enum class MotionModel { NonRigid, Rigid };

/// One detector box (DetectionStage).
struct Detection {
  cv::Rect2f box;        ///< pixels (x, y, width, height) in the colour image, clipped to it
  std::string category;  ///< class name after the class map: "person", "car", ...
  MotionModel model = MotionModel::NonRigid;
  float score = 0;    ///< confidence in [0, 1] (1 for ground truth)
  int truth_id = -1;  ///< simulator instance id when the box came from ground truth, else -1
};

/// Depth-threshold segmentation of one detection (method.md section 1; SegmentationStage).
struct ObjectMask {
  int detection = -1;  ///< index into Frame::detections; -1 when it segments a predicted box
  /// Index into Frame::tracks of the track it belongs to, once a tracking stage has run (the
  /// track matched to its detection, or the track whose predicted box it segments); -1 = none.
  int track = -1;
  cv::Rect roi;  ///< the detection box in whole pixels, clipped; `mask` covers exactly it
  cv::Mat mask;  ///< CV_8UC1, roi-sized, 255 = object pixel
  /// Object depth, m: the far cluster of the candidate box (or, with [Segmentation]
  /// object_depth = mask_median, the median depth of the final mask).
  double d_t = 0;
  double d_o = 0;  ///< occluder depth, m (near cluster); 0 when no occluder was found
  double d_b = 0;  ///< background depth, m (upper half of the box, three-sigma filtered)
  /// The candidate box's other 2-means cluster, m: the depth the object would have had if the
  /// cluster choice had gone the other way; 0 when the samples formed one cluster. A tracker
  /// may compare a track's depth with it too (Tracking.alternative_depth).
  double d_alt = 0;
  double t_min = 0, t_max = 0;  ///< depth thresholds, m: mask = depth in [t_min, t_max]
  bool valid = false;           ///< false: too little valid depth to segment (empty mask, depths 0)
};

enum class TrackState { Tentative, Confirmed, Lost };

/// One Kalman-tracked object (method.md section 2; TrackingStage).
struct Track {
  int id = -1;  ///< stable while the object is tracked, never reused in a run
  TrackState state = TrackState::Tentative;
  cv::Rect2f box;    ///< the filter's box this frame (updated, or predicted while coasting)
  double depth = 0;  ///< the filter's object depth d, m
  std::string category;
  MotionModel model = MotionModel::NonRigid;
  int detection = -1;  ///< index into Frame::detections matched this frame; -1 while coasting
  int hits = 0;        ///< frames matched so far
  int misses = 0;      ///< consecutive frames without a match
};

}  // namespace dynslam::core
