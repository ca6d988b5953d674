#pragma once
// Eigen poses (the pipeline's) to and from MRPT's (the outputs'), exactly: through the 4x4
// homogeneous matrix.
#include <mrpt/math/TPose3D.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace dynslam::system {

inline mrpt::math::TPose3D toTPose3D(const Eigen::Isometry3d& T) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = T.matrix()(r, c);
  return mrpt::poses::CPose3D(m).asTPose();
}

inline Eigen::Isometry3d toIsometry(const mrpt::math::TPose3D& p) {
  const auto m = mrpt::poses::CPose3D(p).getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) T.matrix()(r, c) = m(r, c);
  return T;
}

}  // namespace dynslam::system
