#include "dynslam/segmentation/FloorRemovalStage.h"

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>
#include <string>

namespace dynslam::segmentation {
namespace {

void require(bool ok, const char* key, double value, const char* rule) {
  if (!ok)
    throw std::invalid_argument(std::string(key) + " = " + std::to_string(value) + ": must be " +
                                rule);
}

void validate(const FloorRemovalOptions& o) {
  const auto& p = o.plane;
  require(p.sample_stride_px >= 1, "sample_stride_px", p.sample_stride_px, ">= 1");
  require(p.iterations >= 1, "iterations", p.iterations, ">= 1");
  require(p.inlier_m > 0, "inlier_m", p.inlier_m, "> 0");
  require(p.depth_sigma_z2 >= 0, "depth_sigma_z2", p.depth_sigma_z2, ">= 0");
  require(p.max_depth_m > 0, "max_depth_m", p.max_depth_m, "> 0");
  require(p.max_tilt_deg > 0 && p.max_tilt_deg < 90, "max_tilt_deg", p.max_tilt_deg, "in (0, 90)");
  require(p.min_inliers >= 3, "min_inliers", p.min_inliers, ">= 3");
  require(o.margin_m >= 0, "margin_m", o.margin_m, ">= 0");
  require(o.margin_sigmas >= 0, "margin_sigmas", o.margin_sigmas, ">= 0");
}

}  // namespace

void FloorRemovalOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                             const std::string& s) {
  plane.sample_stride_px = c.read_int(s, "sample_stride_px", plane.sample_stride_px);
  plane.iterations = c.read_int(s, "iterations", plane.iterations);
  plane.inlier_m = c.read_double(s, "inlier_m", plane.inlier_m);
  plane.depth_sigma_z2 = c.read_double(s, "depth_sigma_z2", plane.depth_sigma_z2);
  plane.max_depth_m = c.read_double(s, "max_depth_m", plane.max_depth_m);
  plane.max_tilt_deg = c.read_double(s, "max_tilt_deg", plane.max_tilt_deg);
  plane.min_inliers = c.read_int(s, "min_inliers", plane.min_inliers);
  margin_m = c.read_double(s, "margin_m", margin_m);
  margin_sigmas = c.read_double(s, "margin_sigmas", margin_sigmas);
}

void FloorRemovalOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                           const std::string& s) const {
  core::writeKey(c, s, "sample_stride_px", plane.sample_stride_px,
                 "px; the floor is fitted to depth samples on a grid of this pitch outside the "
                 "masks' boxes");
  core::writeKey(c, s, "iterations", plane.iterations, "RANSAC hypotheses of the floor plane");
  core::writeKey(c, s, "inlier_m", plane.inlier_m,
                 "m; a sample within this (plus 2 sigma(z)) of a plane supports it");
  core::writeKey(c, s, "depth_sigma_z2", plane.depth_sigma_z2,
                 "1/m; depth noise sigma(z) = depth_sigma_z2 z^2");
  core::writeKey(c, s, "max_depth_m", plane.max_depth_m, "m; farther samples are not fitted");
  core::writeKey(c, s, "max_tilt_deg", plane.max_tilt_deg,
                 "deg; the floor's normal is within this of up (the accelerometer's mean "
                 "reading in the frame, else the image's up)");
  core::writeKey(c, s, "min_inliers", plane.min_inliers,
                 "samples on the plane for a floor to count as seen");
  core::writeKey(c, s, "margin_m", margin_m,
                 "m; mask pixels less than this (plus margin_sigmas sigma(z)) above the floor "
                 "leave the mask");
  core::writeKey(c, s, "margin_sigmas", margin_sigmas,
                 "depth-noise sigmas added to margin_m at each pixel's depth");
}

size_t removeFloorPixels(const cv::Mat& depth, const core::CameraIntrinsics& K,
                         const FloorPlane& floor, const FloorRemovalOptions& options,
                         core::ObjectMask& mask) {
  if (mask.mask.empty()) return 0;
  const double sigma2 = options.margin_sigmas * options.plane.depth_sigma_z2;
  // height = z (n . ray) + c with ray = ((u - cx) / fx, (v - cy) / fy, 1): one term per column
  // and one per row.
  std::vector<double> column(size_t(mask.roi.width));
  for (int x = 0; x < mask.roi.width; ++x)
    column[size_t(x)] = floor.normal.x() * (mask.roi.x + x - K.cx) / K.fx;
  size_t removed = 0;
  for (int y = 0; y < mask.roi.height; ++y) {
    const int v = mask.roi.y + y;
    const double row = floor.normal.y() * (v - K.cy) / K.fy + floor.normal.z();
    auto* m = mask.mask.ptr<uint8_t>(y);
    const float* d = depth.ptr<float>(v) + mask.roi.x;
    for (int x = 0; x < mask.roi.width; ++x) {
      const double z = d[x];
      if (!m[x] || !(z > 0)) continue;
      const double height = z * (column[size_t(x)] + row) + floor.offset;
      if (height < options.margin_m + sigma2 * z * z) {
        m[x] = 0;
        ++removed;
      }
    }
  }
  return removed;
}

void FloorRemovalStage::configure(const core::IniConfig& cfg, const std::string& section) {
  try {
    core::loadOptionsStrict(options_, cfg, section);
    validate(options_);
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError("[" + section + "] " + e.what() + " (in " + cfg.source() + ")");
  }
}

void FloorRemovalStage::process(core::Frame& frame) {
  ++frames_;
  if (frame.object_masks.empty() || frame.depth.empty()) return;
  std::vector<cv::Rect> boxes;
  for (const auto& m : frame.object_masks) boxes.push_back(m.roi);
  for (const auto& d : frame.detections) boxes.push_back(d.box);
  const auto floor =
      fitFloorPlane(frame.depth, frame.intrinsics, boxes, upInCamera(frame), options_.plane);
  for (const auto& m : frame.object_masks) maskPixels_ += size_t(cv::countNonZero(m.mask));
  if (!floor) return;
  ++floorFrames_;
  for (auto& m : frame.object_masks)
    removedPixels_ += removeFloorPixels(frame.depth, frame.intrinsics, *floor, options_, m);
}

void FloorRemovalStage::finish() {
  MRPT_LOG_INFO_STREAM("floor found in " << floorFrames_ << " of " << frames_ << " frames; "
                                         << removedPixels_ << " of " << maskPixels_
                                         << " mask pixels were floor");
}

std::vector<std::pair<std::string, double>> FloorRemovalStage::statistics() const {
  return {{"frames", double(frames_)},
          {"floor_frames", double(floorFrames_)},
          {"removed_pixel_fraction", maskPixels_ ? double(removedPixels_) / maskPixels_ : 0.0}};
}

}  // namespace dynslam::segmentation
