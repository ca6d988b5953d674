#pragma once
// Which object a feature belongs to (method.md section 3: "a feature inside an object mask
// belongs to that object"): the tracked objects' masks of the frame (core::ObjectMask, roi-sized
// with 255 = object), each named by the Track::id of its track.
#include <dynslam/core/Frame.h>

#include <vector>

namespace dynslam::frontend {

struct ObjectRegion {
  int object_id = -1;  ///< Track::id
  core::MotionModel model = core::MotionModel::NonRigid;
  cv::Rect roi;
  cv::Mat mask;        ///< CV_8UC1, roi-sized
  double depth = 0;    ///< the segmentation's d_t; where masks overlap, the nearer one wins
};

/// One region per valid, non-empty mask whose track is known: ObjectMask::track, or, when a
/// tracking stage left it at -1, the track matched to the mask's detection
/// (Track::detection). Masks of no track are skipped (no id to give their features). Sorted
/// nearest first.
std::vector<ObjectRegion> objectRegions(const core::Frame& frame);

/// One region per mask left invalid for too little depth (the object is beyond the depth
/// camera's range, or its depth is missing) whose track is known: the detection box as `roi`,
/// no `mask`, depth 0. In input order.
std::vector<ObjectRegion> depthlessObjectBoxes(const core::Frame& frame);

/// The region holding `pixel`, nearest first; nullptr for background.
const ObjectRegion* regionAt(const std::vector<ObjectRegion>& regions, const cv::Point2f& pixel);

}  // namespace dynslam::frontend
