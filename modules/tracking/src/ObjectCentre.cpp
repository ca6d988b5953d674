#include "dynslam/tracking/ObjectCentre.h"

#include <dynslam/core/Median.h>

#include <Eigen/Geometry>

#include <vector>

namespace dynslam::tracking {

std::optional<ObjectCentre> measureObjectCentre(const cv::Mat& depth,
                                                const core::CameraIntrinsics& K,
                                                const core::ObjectMask& mask,
                                                const Eigen::Vector3d& up_camera,
                                                const ObjectCentreParams& params) {
  if (mask.mask.empty() || depth.empty() || depth.type() != CV_32FC1 || K.fx <= 0 || K.fy <= 0)
    return std::nullopt;
  const cv::Rect roi = mask.roi & cv::Rect(0, 0, depth.cols, depth.rows);
  std::vector<Eigen::Vector3d> points;
  const int s = params.pixel_stride;
  for (int y = roi.y - mask.roi.y; y < roi.y - mask.roi.y + roi.height; y += s) {
    const auto* m = mask.mask.ptr<uint8_t>(y);
    const float* d = depth.ptr<float>(mask.roi.y + y);
    for (int x = roi.x - mask.roi.x; x < roi.x - mask.roi.x + roi.width; x += s) {
      const int u = mask.roi.x + x;
      const double z = d[u];
      if (!m[x] || !(z > 0)) continue;
      points.emplace_back((u - K.cx) / K.fx * z, (mask.roi.y + y - K.cy) / K.fy * z, z);
    }
  }
  if (int(points.size()) < params.min_points) return std::nullopt;

  const Eigen::Vector3d up = up_camera.normalized();
  const Eigen::Vector3d median = core::componentwiseUpperMedian(points);
  Eigen::Vector3d along = median - median.dot(up) * up;
  if (along.norm() < 1e-6 * median.norm() || !(along.norm() > 0)) return std::nullopt;
  along.normalize();
  const Eigen::Vector3d across = up.cross(along);

  std::vector<double> a, f, h;
  for (const auto& p : points) {
    a.push_back(p.dot(across));
    f.push_back(p.dot(along));
    h.push_back(p.dot(up));
  }
  // The 2nd to 98th percentile, widened by 1 / 0.96 (exact for pixels spread evenly): a few
  // stray pixels of another surface do not stretch the body.
  const double width = (core::upperPercentile(a, 0.98) - core::upperPercentile(a, 0.02)) / 0.96;
  const double h_low = core::upperPercentile(h, 0.02), h_high = core::upperPercentile(h, 0.98);
  const double height_low = h_low - 0.02 * (h_high - h_low) / 0.96,
               height_high = h_high + 0.02 * (h_high - h_low) / 0.96;
  const double thickness = std::min(params.thickness_fraction * width, params.max_thickness_m);

  ObjectCentre out;
  out.points = int(points.size());
  out.extent = {width, thickness, height_high - height_low};
  out.centre = core::upperMedian(a) * across + (core::upperMedian(f) + 0.5 * thickness) * along +
               0.5 * (height_low + height_high) * up;
  Eigen::Matrix3d axes;
  axes << across, along, up;
  const Eigen::Vector3d variances(params.sigma_across_m * params.sigma_across_m,
                                  params.sigma_along_m * params.sigma_along_m,
                                  params.sigma_up_m * params.sigma_up_m);
  out.covariance = axes * variances.asDiagonal() * axes.transpose();
  return out;
}

}  // namespace dynslam::tracking
