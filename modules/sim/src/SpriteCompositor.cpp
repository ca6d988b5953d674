#include <dynslam/sim/SpriteCompositor.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dynslam::sim {
namespace {

/// The sprite's plane in camera coordinates: through the foot, spanned by `up` and `right`
/// (image right when not mirrored), its normal `toward` the camera; `ppm` sprite pixels a metre.
struct SpritePlane {
  Eigen::Vector3d foot, up, right, toward;
  double ppm = 1;
};

/// The plane for `placement`, or false when the foot is not in front of the camera.
bool planeOf(const SpriteFrame& sprite, const SpritePlacement& p,
             const Eigen::Isometry3d& T_world_camera, SpritePlane& plane) {
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  plane.foot = T_camera_world * p.foot_world;
  if (plane.foot.z() < 0.1) return false;
  plane.up = (T_camera_world.linear() * p.up_world).normalized();
  Eigen::Vector3d toward = -plane.foot;
  toward -= plane.up * plane.up.dot(toward);
  if (toward.norm() < 1e-6) return false;  // looking straight down on the person
  plane.toward = toward.normalized();
  plane.right = plane.up.cross(plane.toward);
  if (plane.right.x() < 0) plane.right = -plane.right;
  plane.ppm = sprite.height_px / p.height_m;
  return true;
}

/// The image box of the sprite's crop on the plane, clipped to the image.
cv::Rect imageBox(const SpriteFrame& sprite, const SpritePlane& plane,
                  const core::CameraIntrinsics& K) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (const double u : {0.0, double(sprite.bgra.cols)})
    for (const double v : {0.0, double(sprite.bgra.rows)}) {
      const double l = (u - sprite.foot.x) / plane.ppm, h = (sprite.foot.y - v) / plane.ppm;
      const Eigen::Vector3d q = plane.foot + plane.up * h + plane.right * l;
      if (q.z() < 0.05) return {};
      const double x = K.fx * q.x() / q.z() + K.cx, y = K.fy * q.y() / q.z() + K.cy;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  const cv::Rect box(cv::Point(int(std::floor(x0)), int(std::floor(y0))),
                     cv::Point(int(std::ceil(x1)) + 1, int(std::ceil(y1)) + 1));
  return box & cv::Rect(0, 0, K.width, K.height);
}

/// The sprite at (u, v), pixel centres at +0.5, interpolated between its four nearest pixels (a
/// person nearer than in the video is enlarged without blocks).
cv::Vec4b bilinear(const cv::Mat& bgra, double u, double v) {
  const double x = std::clamp(u - 0.5, 0.0, bgra.cols - 1.0);
  const double y = std::clamp(v - 0.5, 0.0, bgra.rows - 1.0);
  const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, bgra.cols - 1),
            y1 = std::min(y0 + 1, bgra.rows - 1);
  const double fx = x - x0, fy = y - y0;
  cv::Vec4b out;
  for (int c = 0; c < 4; ++c) {
    const double top =
        (1 - fx) * bgra.at<cv::Vec4b>(y0, x0)[c] + fx * bgra.at<cv::Vec4b>(y0, x1)[c];
    const double bottom =
        (1 - fx) * bgra.at<cv::Vec4b>(y1, x0)[c] + fx * bgra.at<cv::Vec4b>(y1, x1)[c];
    out[c] = cv::saturate_cast<uchar>((1 - fy) * top + fy * bottom);
  }
  return out;
}

}  // namespace

SpriteDraw compositeSprite(const SpriteFrame& sprite, const SpritePlacement& placement,
                           uint16_t label, const core::CameraIntrinsics& K,
                           const Eigen::Isometry3d& T_world_camera, RenderOutput& frame) {
  if (sprite.bgra.type() != CV_8UC4 || frame.rgb.type() != CV_8UC3 ||
      frame.depth.type() != CV_32FC1 || frame.label.type() != CV_16UC1 ||
      frame.rgb.size() != cv::Size(K.width, K.height) || frame.depth.size() != frame.rgb.size() ||
      frame.label.size() != frame.rgb.size())
    throw std::invalid_argument(
        "compositeSprite: a BGRA sprite and an rgb/depth/label frame of "
        "the camera's size are needed");
  SpriteDraw draw;
  SpritePlane plane;
  if (!planeOf(sprite, placement, T_world_camera, plane)) return draw;
  // The crop's box holds the silhouette and the crop's empty corners (a walker's crop is as wide
  // as the stride); the amodal box is the silhouette's own.
  const cv::Rect crop = imageBox(sprite, plane, K);
  cv::Point lo(K.width, K.height), hi(-1, -1);
  const double halfWidth = placement.body_width_m / 2, halfDepth = placement.body_depth_m / 2;
  for (int y = crop.y; y < crop.br().y; ++y)
    for (int x = crop.x; x < crop.br().x; ++x) {
      // The pixel's ray meets the plane at P; (l, h) are P's coordinates on it.
      const Eigen::Vector3d ray((x - K.cx) / K.fx, (y - K.cy) / K.fy, 1.0);
      const double s = plane.toward.dot(plane.foot) / plane.toward.dot(ray);
      if (!(s > 0)) continue;
      const Eigen::Vector3d P = s * ray, d = P - plane.foot;
      const double l = plane.right.dot(d), h = plane.up.dot(d);
      const double u = sprite.foot.x + (placement.mirrored ? -l : l) * plane.ppm;
      const double v = sprite.foot.y - h * plane.ppm;
      if (u < 0 || v < 0 || u >= sprite.bgra.cols || v >= sprite.bgra.rows) continue;
      const cv::Vec4b texel = bilinear(sprite.bgra, u, v);
      if (texel[3] < 128) continue;
      ++draw.pixels;
      lo = cv::Point(std::min(lo.x, x), std::min(lo.y, y));
      hi = cv::Point(std::max(hi.x, x), std::max(hi.y, y));
      // The front of the elliptical cross-section round the plane's axis (arms beyond the
      // body's width lie on the plane).
      const double across = std::min(1.0, std::abs(l) / halfWidth);
      const double z = (P + plane.toward * halfDepth * std::sqrt(1 - across * across)).z();
      float& depth = frame.depth.at<float>(y, x);
      if (depth > 0 && depth <= z) continue;
      depth = float(z);
      frame.rgb.at<cv::Vec3b>(y, x) = cv::Vec3b(texel[0], texel[1], texel[2]);
      frame.label.at<uint16_t>(y, x) = label;
      ++draw.visible;
    }
  if (draw.pixels > 0) draw.box = cv::Rect(lo, hi + cv::Point(1, 1));
  return draw;
}

}  // namespace dynslam::sim
