#include "dynslam/estimator/factors/PinholeProjection.h"

namespace dynslam::estimator {

Eigen::Vector2d PinholeCamera::project(const Eigen::Vector3d& p,
                                       Eigen::Matrix<double, 2, 3>* jacobian) const {
  const double invZ = 1.0 / p.z();
  const double x = p.x() * invZ, y = p.y() * invZ;
  if (jacobian) {
    *jacobian << fx * invZ, 0, -fx * x * invZ,  //
        0, fy * invZ, -fy * y * invZ;
  }
  return {fx * x + cx, fy * y + cy};
}

Eigen::Vector3d PinholeCamera::bearing(const Eigen::Vector2d& pixel) const {
  return {(pixel.x() - cx) / fx, (pixel.y() - cy) / fy, 1.0};
}

}  // namespace dynslam::estimator
