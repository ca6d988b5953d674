#include "dynslam/segmentation/FloorRemovalStage.h"

namespace dynslam::segmentation {

void FloorRemovalOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  auto& p = plane;
  v.key("sample_stride_px", p.sample_stride_px, Range::atLeast(1),
        "px; the floor is fitted to depth samples on a grid of this pitch outside the masks' "
        "boxes");
  v.key("iterations", p.iterations, Range::atLeast(1), "RANSAC hypotheses of the floor plane");
  v.key("inlier_m", p.inlier_m, Range::above(0),
        "m; a sample within this (plus 2 sigma(z)) of a plane supports it");
  v.key("depth_sigma_z2", p.depth_sigma_z2, Range::atLeast(0),
        "1/m; depth noise sigma(z) = depth_sigma_z2 z^2");
  v.key("max_depth_m", p.max_depth_m, Range::above(0), "m; farther samples are not fitted");
  v.key("max_tilt_deg", p.max_tilt_deg, Range{0, 90, true, true},
        "deg; the floor's normal is within this of up (the accelerometer's mean reading in the "
        "frame, else the image's up)");
  v.key("min_inliers", p.min_inliers, Range::atLeast(3),
        "samples on the plane for a floor to count as seen");
  v.key("margin_m", margin_m, Range::atLeast(0),
        "m; mask pixels less than this above the floor (or below it) leave the mask");
}

size_t removeFloorPixels(const cv::Mat& depth, const core::CameraIntrinsics& K,
                         const FloorPlane& floor, const FloorRemovalOptions& options,
                         core::ObjectMask& mask) {
  if (mask.mask.empty()) return 0;
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
      if (height < options.margin_m) {
        m[x] = 0;
        ++removed;
      }
    }
  }
  return removed;
}

void FloorRemovalStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
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
