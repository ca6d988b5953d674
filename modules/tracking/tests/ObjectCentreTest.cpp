#include "CylinderFrame.h"

#include <dynslam/tracking/ObjectCentre.h>

#include <gtest/gtest.h>

using namespace dynslam;
using namespace dynslam::tracking;
using test_support::Cylinder;
using test_support::cylinderFrame;

namespace {

const Eigen::Vector3d kUp(0, -1, 0);  // the camera level: up is the image's up

TEST(ObjectCentre, ABodysCentreLiesBehindItsSeenSurface) {
  const Cylinder body{0.5, 3.0, 0.2};
  const core::Frame f = cylinderFrame(0, body, 1);
  // A round body is as deep as it is wide; its seen surface's median point lies r cos 30 deg in
  // front of the axis (pixels even in the across coordinate), so the fraction that puts the
  // centre on the axis is cos 30 deg.
  ObjectCentreParams p;
  p.thickness_fraction = std::sqrt(3.0) / 2;
  p.pixel_stride = 1;
  const auto c = measureObjectCentre(f.depth, f.intrinsics, f.object_masks[0], kUp, p);
  ASSERT_TRUE(c);
  const Eigen::Vector3d axis(body.x, 0.05, body.z);  // middle of y_top .. y_bottom
  EXPECT_NEAR(c->centre.x(), axis.x(), 0.02) << c->centre.transpose();
  EXPECT_NEAR(c->centre.z(), axis.z(), 0.02) << c->centre.transpose();
  EXPECT_NEAR(c->centre.y(), axis.y(), 0.1);
  EXPECT_NEAR(c->extent.x(), 2 * body.radius, 0.03);
  EXPECT_NEAR(c->extent.z(), body.y_bottom - body.y_top, 0.2);

  // Without the assumed depth the centre is the seen surface, well in front of the axis.
  p.thickness_fraction = 0;
  const auto surface = measureObjectCentre(f.depth, f.intrinsics, f.object_masks[0], kUp, p);
  ASSERT_TRUE(surface);
  const double along =
      (Eigen::Vector3d(body.x, 0, body.z))
          .normalized()
          .dot(Eigen::Vector3d(surface->centre.x() - body.x, 0, surface->centre.z() - body.z));
  EXPECT_LT(along, -0.15);
}

TEST(ObjectCentre, ItsCovarianceIsWidestAlongTheLineOfSight) {
  const core::Frame f = cylinderFrame(0, Cylinder{0.0, 4.0}, 1);
  const auto c = measureObjectCentre(f.depth, f.intrinsics, f.object_masks[0], kUp, {});
  ASSERT_TRUE(c);
  const ObjectCentreParams p;
  EXPECT_NEAR(c->covariance(2, 2), p.sigma_along_m * p.sigma_along_m, 1e-6);
  EXPECT_NEAR(c->covariance(0, 0), p.sigma_across_m * p.sigma_across_m, 1e-6);
  EXPECT_NEAR(c->covariance(1, 1), p.sigma_up_m * p.sigma_up_m, 1e-6);
}

TEST(ObjectCentre, TooFewPixelsWithDepthMeasureNothing) {
  core::Frame f = cylinderFrame(0, Cylinder{0.0, 3.0}, 1);
  f.depth.setTo(0);
  EXPECT_FALSE(measureObjectCentre(f.depth, f.intrinsics, f.object_masks[0], kUp, {}));
  core::ObjectMask empty;
  EXPECT_FALSE(measureObjectCentre(f.depth, f.intrinsics, empty, kUp, {}));
}

}  // namespace
