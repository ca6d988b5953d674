#include "dynslam/estimator/FramePoseTracker.h"

#include "dynslam/estimator/factors/PinholeProjection.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include <cmath>

namespace dynslam::estimator {

bool withinStep(const Eigen::Isometry3d& step, double max_m, double max_deg) {
  return step.matrix().allFinite() && step.translation().norm() <= max_m &&
         Eigen::AngleAxisd(step.rotation()).angle() * 180.0 / M_PI <= max_deg;
}

bool acceptPnpPose(const Eigen::Isometry3d& tracked, const Eigen::Isometry3d& predicted,
                   bool predictedByImu, const std::optional<Eigen::Isometry3d>& last,
                   const PnpPoseGate& gate) {
  if (predictedByImu && gate.imu_max_m > 0 && gate.imu_max_deg > 0)
    return withinStep(predicted.inverse() * tracked, gate.imu_max_m, gate.imu_max_deg);
  return withinStep(predicted.inverse() * tracked, gate.max_m, gate.max_deg) ||
         (last && withinStep(last->inverse() * tracked, gate.max_m, gate.max_deg));
}

std::optional<TrackedPose> trackFramePose(
    const PinholeCamera& camera,
    const std::vector<std::pair<std::int64_t, Eigen::Vector3d>>& landmarks,
    const std::map<std::int64_t, Eigen::Vector2d>& pixels, const Eigen::Isometry3d& predicted,
    const FramePoseTrackerParams& params) {
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (const auto& [id, world] : landmarks) {
    const auto it = pixels.find(id);
    if (it == pixels.end()) continue;
    object.emplace_back(world.x(), world.y(), world.z());
    image.emplace_back(it->second.x(), it->second.y());
  }
  TrackedPose out;
  out.candidates = int(object.size());
  if (out.candidates < params.min_inliers) return std::nullopt;

  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  const Eigen::Isometry3d T_cw = predicted.inverse();
  cv::Mat R, rvec, tvec;
  cv::eigen2cv(Eigen::Matrix3d(T_cw.rotation()), R);
  cv::Rodrigues(R, rvec);
  cv::eigen2cv(Eigen::Vector3d(T_cw.translation()), tvec);
  std::vector<int> inliers;
  if (!cv::solvePnPRansac(object, image, K, cv::noArray(), rvec, tvec, true, 100,
                          float(params.ransac_threshold_px), 0.99, inliers, cv::SOLVEPNP_ITERATIVE))
    return std::nullopt;
  out.inliers = int(inliers.size());
  if (out.inliers < params.min_inliers) return std::nullopt;
  std::vector<cv::Point3d> objectIn;
  std::vector<cv::Point2d> imageIn;
  for (int i : inliers) {
    objectIn.push_back(object[size_t(i)]);
    imageIn.push_back(image[size_t(i)]);
  }
  cv::solvePnPRefineLM(objectIn, imageIn, K, cv::noArray(), rvec, tvec);
  cv::Rodrigues(rvec, R);
  Eigen::Matrix3d Re;
  Eigen::Vector3d te;
  cv::cv2eigen(R, Re);
  cv::cv2eigen(tvec, te);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Re;
  T.translation() = te;
  out.T_world_camera = T.inverse();
  return out;
}

}  // namespace dynslam::estimator
