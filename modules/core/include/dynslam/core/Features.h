#pragma once
// What the visual front-end adds to a Frame (method.md sections 3 and 4): tracked point
// features with their class and object, the motion state of each tracked object, and the rigid
// point sets found on dynamic objects. MRPT-free, like Frame.h.
#include <Eigen/Geometry>
#include <opencv2/core/types.hpp>

#include <cstdint>
#include <vector>

namespace dynslam::core {

/// The role a feature plays in the estimator (method.md section 3).
enum class FeatureClass {
  Static,    ///< constrains the camera: background, or an object that is not moving
  Rigid,     ///< on a dynamic rigid object, or in a rigid point set of a non-rigid one
  NonRigid,  ///< on a dynamic non-rigid object, outside every rigid set
};

/// One tracked Shi-Tomasi corner in this frame.
struct Feature {
  std::int64_t id = -1;  ///< stable while the corner is tracked, never reused in a run
  cv::Point2f pixel;     ///< colour-image pixel (x right, y down)
  float depth = 0;       ///< metres along the optical axis from the depth image; 0 = none
  /// The depth image holds an edge (a reading nearer or farther by the gap, or none) within
  /// FeatureTracking's depth_edge_radius_px: the estimator leaves this reading out (not the
  /// method; the front-end still uses it).
  bool depth_at_edge = false;
  int track_length = 1;  ///< frames this corner has been tracked, this one included
  /// px/s over the last frame interval (a new corner: the frame's median flow, a guess). The
  /// estimator moves the pixel along it by the camera-IMU time offset (VINS-Fusion's t_d).
  cv::Point2f velocity{0.f, 0.f};
  FeatureClass feature_class = FeatureClass::Static;
  int object_id = -1;  ///< Track::id of the object whose mask holds it; -1 = background
};

/// Whether a tracked object moves (method.md section 3: mean scene flow / frame interval).
struct ObjectMotionState {
  int object_id = -1;    ///< Track::id
  double speed = 0;      ///< m/s, mean |scene flow| of its features over the frame interval
  int features = 0;      ///< features with depth in both frames that the speed averages
  bool dynamic = false;  ///< speed above the threshold
};

/// A rigid point set (method.md section 4) and its motion from the previous frame to this one.
/// Points are in camera coordinates: q = R p + t maps a member's position p in the previous
/// frame's camera frame to its position q in this frame's camera frame (the method's
/// registration; it contains the camera's own motion).
struct RigidSet {
  int object_id = -1;                 ///< Track::id of the object it lies on
  std::vector<std::int64_t> members;  ///< Feature::id of the inliers
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d virtual_centroid = Eigen::Vector3d::Zero();  ///< camera frame, this frame
};

/// The estimated world pose of a tracked object (a rigid object, or the rigid point set of a
/// non-rigid one) at this frame: its frame is the rigid set's first virtual centroid with the
/// world's axes, carried along by the set's motion.
struct ObjectPose {
  int object_id = -1;  ///< Track::id
  Eigen::Isometry3d T_world_object = Eigen::Isometry3d::Identity();
};

}  // namespace dynslam::core
