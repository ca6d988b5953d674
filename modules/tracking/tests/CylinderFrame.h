#pragma once
// A test frame showing one upright cylinder (a body) in front of a camera that sees nothing
// else: depth rendered exactly, its mask, and a confirmed track on it.
#include <dynslam/core/Frame.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

namespace dynslam::tracking::test_support {

struct Cylinder {
  double x = 0, z = 3;                  ///< axis position in the camera frame, m
  double radius = 0.2;                  ///< m
  double y_top = -0.8, y_bottom = 0.9;  ///< camera y (down) of its ends, m
};

/// Depth of the cylinder's near surface (0 elsewhere), a mask of its pixels and track `track_id`.
inline core::Frame cylinderFrame(double t, const Cylinder& c, int track_id,
                                 const std::string& category = "person") {
  core::Frame f;
  f.t = t;
  f.intrinsics = dynslam::testing::vgaCamera();
  const auto& K = f.intrinsics;
  f.depth = cv::Mat(K.height, K.width, CV_32FC1, cv::Scalar(0.0f));
  cv::Mat mask(K.height, K.width, CV_8UC1, cv::Scalar(0));
  for (int v = 0; v < K.height; ++v)
    for (int u = 0; u < K.width; ++u) {
      // The ray (a, b, 1) t meets (a t - x)^2 + (t - z)^2 = r^2 first at the smaller root.
      const double a = (u - K.cx) / K.fx, b = (v - K.cy) / K.fy;
      const double A = a * a + 1, B = -2 * (a * c.x + c.z),
                   C = c.x * c.x + c.z * c.z - c.radius * c.radius;
      const double disc = B * B - 4 * A * C;
      if (disc < 0) continue;
      const double depth = (-B - std::sqrt(disc)) / (2 * A);
      if (b * depth < c.y_top || b * depth > c.y_bottom) continue;
      f.depth.at<float>(v, u) = float(depth);
      mask.at<uint8_t>(v, u) = 255;
    }
  core::ObjectMask m;
  m.roi = cv::boundingRect(mask);
  m.mask = mask(m.roi).clone();
  m.valid = !m.roi.empty();
  m.track = 0;
  f.object_masks.push_back(m);
  core::Track track;
  track.id = track_id;
  track.state = core::TrackState::Confirmed;
  track.category = category;
  f.tracks.push_back(track);
  f.T_world_camera = Eigen::Isometry3d::Identity();
  return f;
}

}  // namespace dynslam::tracking::test_support
