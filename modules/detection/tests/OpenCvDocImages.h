#pragma once
// Real pedestrian images from Debian's opencv-doc package (basketball1.png, vtest.avi), shared by
// the detector tests; a test skips when the package is absent.
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace dynslam::detection::testing {

/// /usr/share/doc/opencv-doc/examples/data/<name>, or "" when that file is absent.
std::string openCvDocFile(const std::string& name);

/// The frames of vtest.avi with these indices (768x576 BGR); empty when it cannot be read.
std::vector<cv::Mat> vtestFrames(const std::vector<int>& indices);

}  // namespace dynslam::detection::testing

#define DYNSLAM_REQUIRE_OPENCV_DOC(var, name)                                 \
  const std::string var = ::dynslam::detection::testing::openCvDocFile(name); \
  if (var.empty())                                                            \
  GTEST_SKIP() << "needs " << (name) << " of Debian's opencv-doc package "    \
               << "(/usr/share/doc/opencv-doc/examples/data/), which is absent"
