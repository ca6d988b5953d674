#pragma once
// A real person's pixels (one SpriteFrame) standing in a rendered or real RGB-D frame as a 3-D
// body, not a flat card: the sprite lies on a vertical plane through its foot point that faces
// the camera, scaled to the person's true height, and each pixel's depth is the front of an
// elliptical body cross-section (width x depth) round the plane's vertical axis, so depth
// segmentation and scene flow see a body. Pixels go in only where the person is nearer than what
// the frame holds (or the frame has no depth there), as Compositor.h does for rendered movers.
#include <dynslam/core/Frame.h>
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/sim/SpriteBank.h>

#include <Eigen/Geometry>

#include <cstdint>

namespace dynslam::sim {

/// Where a sprite person stands in one frame.
struct SpritePlacement {
  Eigen::Vector3d foot_world = Eigen::Vector3d::Zero();  ///< the point it stands on
  Eigen::Vector3d up_world = Eigen::Vector3d::UnitZ();   ///< the floor's normal
  double height_m = 1.75;                                ///< head to foot
  bool mirrored = false;  ///< draw the sprite flipped left-right (walking the other way)
  double body_width_m = 0.35, body_depth_m = 0.25;  ///< the elliptical cross-section
};

/// What compositeSprite drew: the person's whole (amodal) box in the image, clipped to it, its
/// pixel count there, and how many of them were nearer than the frame (visible).
struct SpriteDraw {
  cv::Rect box;     ///< the person's amodal box: round every pixel of the silhouette, hidden or not
  int pixels = 0;   ///< silhouette pixels in the image
  int visible = 0;  ///< of them, drawn (nearer than the frame's depth)
};

/// Draws `sprite` at `placement` into `frame` (rgb CV_8UC3, depth CV_32FC1 m along the optical
/// axis, label CV_16UC1) with label `label`, for a camera with intrinsics `camera` at
/// `T_world_camera`. A frame pixel takes the sprite's colour, depth and label where the sprite's
/// alpha is at least half and its depth is nearer than the frame's (or the frame's is 0).
/// Nothing is drawn when the foot is behind the camera or the person is out of view.
SpriteDraw compositeSprite(const SpriteFrame& sprite, const SpritePlacement& placement,
                           uint16_t label, const core::CameraIntrinsics& camera,
                           const Eigen::Isometry3d& T_world_camera, RenderOutput& frame);

}  // namespace dynslam::sim
