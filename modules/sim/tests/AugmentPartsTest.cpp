// The pieces of augment mode on synthetic data (no dataset needed): the floor is the lowest
// large plane even when a table top holds more points, the spline fit smooths jittered poses
// and unwraps yaw, compositing keeps real pixels byte-equal, and the planner keeps agents on
// clear floor, apart and away from the camera, or says why it cannot.
#include <dynslam/sim/Compositor.h>
#include <dynslam/sim/FloorMap.h>
#include <dynslam/sim/FloorPlane.h>
#include <dynslam/sim/FloorPlanner.h>
#include <dynslam/sim/GroundTruthSpline.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <cmath>
#include <iostream>

namespace dynslam::sim {
namespace {

constexpr double kDeg = M_PI / 180;

/// A grid of points on z = height over [x0, x1] x [y0, y1], every `step` m, as one PointGrid.
PointGrid horizontalPatch(double x0, double x1, double y0, double y1, double height, double step) {
  PointGrid g;
  g.cols = static_cast<int>((x1 - x0) / step) + 1;
  g.rows = static_cast<int>((y1 - y0) / step) + 1;
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      g.points.emplace_back(x0 + c * step, y0 + r * step, height);
      g.valid.push_back(true);
    }
  return g;
}

TEST(AugmentFloorPlane, FindsTheFloorUnderALargerTableTop) {
  // Floor 2 m x 1 m at z = 0; a table top 2 m x 2 m at 0.75 m (twice the floor's points) over
  // other floor; a 15 deg error in the up hint.
  std::vector<PointGrid> grids{horizontalPatch(0, 2, 0, 1, 0.0, 0.02),
                               horizontalPatch(0, 2, 2, 4, 0.75, 0.02)};
  const Eigen::Vector3d hint =
      Eigen::AngleAxisd(15 * kDeg, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
  std::mt19937_64 rng(5);
  const FloorFit fit = fitFloorPlane(grids, hint, {}, rng);
  EXPECT_LT(std::acos(fit.plane.normal.z()), 0.1 * kDeg);
  EXPECT_NEAR(fit.plane.offset, 0.0, 1e-6);
  EXPECT_EQ(fit.inliers, grids[0].points.size());

  // Only a 45 deg ramp: no candidate within the 30 deg tilt limit, an error, not a wrong floor.
  std::vector<PointGrid> tilted{horizontalPatch(0, 2, 0, 1, 0.0, 0.02)};
  for (auto& p : tilted[0].points) p.z() = p.x();  // a 45 deg ramp
  EXPECT_THROW(fitFloorPlane(tilted, Eigen::Vector3d::UnitZ(), {}, rng), std::runtime_error);
}

TEST(AugmentFloorPlane, BackProjectsAndBuildsAnUprightFrame) {
  core::CameraIntrinsics k{500, 500, 3.5, 2.5, 8, 6};
  cv::Mat depth(6, 8, CV_32FC1, cv::Scalar(2.0f));
  depth.at<float>(0, 0) = 0;  // invalid
  const PointGrid g = backProject(depth, k, Eigen::Isometry3d::Identity(), 2, 3.0);
  ASSERT_EQ(g.rows, 3);
  ASSERT_EQ(g.cols, 4);
  EXPECT_FALSE(g.valid[0]);
  EXPECT_TRUE(g.points[5].isApprox(Eigen::Vector3d((2 - 3.5) * 2 / 500, (2 - 2.5) * 2 / 500, 2)));

  const Plane plane{Eigen::Vector3d(0, 0.6, 0.8), 1.0};
  const Eigen::Isometry3d T = floorFrame(plane, Eigen::Vector3d(3, 4, 5), Eigen::Vector3d::UnitX());
  EXPECT_TRUE(T.linear().col(2).isApprox(plane.normal));
  EXPECT_NEAR(plane.height(T.translation()), 0.0, 1e-12);
  EXPECT_NEAR(T.linear().determinant(), 1.0, 1e-12);
  EXPECT_TRUE(T.linear().col(0).isApprox(Eigen::Vector3d::UnitX()));
}

TEST(AugmentSpline, SmoothsJitterAndFollowsTwoTurnsOfYaw) {
  // A body circling twice in 8 s (yaw wraps four times), with 3 mm / 0.2 deg of jitter.
  std::mt19937_64 rng(2);
  std::normal_distribution<double> jitter(0.0, 1.0);
  core::Trajectory truth, noisy;
  for (int i = 0; i <= 240; ++i) {
    const double t = i / 30.0, a = 2 * M_PI * t / 4;
    core::StampedPose p;
    p.t = t;
    p.T_world_body.translation() =
        Eigen::Vector3d(std::cos(a), std::sin(a), 1.4 + 0.05 * std::sin(3 * t));
    p.T_world_body.linear() = rotationFromYawPitchRoll({a + M_PI / 2, 0.3 * std::sin(t), 0.1});
    truth.push_back(p);
    p.T_world_body.translation() += 0.003 * Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
    p.T_world_body.linear() =
        p.T_world_body.linear() *
        rotationFromYawPitchRoll(0.2 * kDeg *
                                 Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
    noisy.push_back(p);
  }
  const SplineTrajectory spline = fitSplineToPoses(noisy, 0.2);
  const SplineFitError to_truth = splineFitError(spline, truth);
  // The jitter itself, as the same statistics: the spline must be nearer the truth than it.
  const SplineFitError jitter_size = splineFitError(fitSplineToPoses(truth, 0.2), noisy);
  std::cout << "spline vs truth: median " << to_truth.median_position * 1e3 << " mm, max "
            << to_truth.max_position * 1e3 << " mm, median " << to_truth.median_rotation / kDeg
            << " deg, max " << to_truth.max_rotation / kDeg << " deg (jitter: median "
            << jitter_size.median_position * 1e3 << " mm, " << jitter_size.median_rotation / kDeg
            << " deg)\n";
  EXPECT_LT(to_truth.median_position, 0.5 * jitter_size.median_position);
  EXPECT_LT(to_truth.median_rotation, 0.5 * jitter_size.median_rotation);
  EXPECT_LT(to_truth.max_position, 0.01);
  EXPECT_LT(to_truth.max_rotation, 1 * kDeg);
  EXPECT_GE(spline.endTime(), truth.back().t);

  EXPECT_THROW(fitSplineToPoses({truth[0]}, 0.1), std::invalid_argument);
  EXPECT_THROW(fitSplineToPoses({truth[1], truth[0]}, 0.1), std::invalid_argument);
}

TEST(AugmentCompositor, NearerRenderedPixelsWinAndRealOnesStayExact) {
  cv::Mat real_rgb(40, 60, CV_8UC3), real_depth(40, 60, CV_32FC1, cv::Scalar(2.0f));
  cv::randu(real_rgb, 0, 255);
  real_depth(cv::Rect(0, 0, 10, 40)).setTo(0);  // invalid real depth on the left
  RenderOutput rendered;
  rendered.rgb = cv::Mat(40, 60, CV_8UC3, cv::Scalar(10, 200, 30));
  rendered.depth = cv::Mat(40, 60, CV_32FC1, cv::Scalar(0));
  rendered.label = cv::Mat(40, 60, CV_16UC1, cv::Scalar(0));
  rendered.depth(cv::Rect(5, 5, 20, 20)).setTo(1.0f);   // in front (and over the invalid strip)
  rendered.depth(cv::Rect(35, 5, 20, 20)).setTo(3.0f);  // behind the real surface
  rendered.label.setTo(7, rendered.depth > 0);
  RenderOutput out;
  const cv::Mat mask = compositeOverReal(rendered, real_rgb, real_depth, out);
  EXPECT_EQ(cv::countNonZero(mask), 400);
  EXPECT_EQ(cv::countNonZero(out.label), 400);
  EXPECT_EQ(cv::countNonZero(mask != (out.label == 7)), 0);

  RgbdNoiseOptions noise;
  noise.colour_sigma = 5;
  std::mt19937_64 rng(3);
  applyRgbdNoiseMasked(out, mask, noise, rng);
  cv::Mat rgb_diff, depth_diff;
  cv::absdiff(out.rgb, real_rgb, rgb_diff);
  cv::absdiff(out.depth, real_depth, depth_diff);
  rgb_diff.setTo(0, mask);
  depth_diff.setTo(0, mask);
  EXPECT_EQ(cv::countNonZero(rgb_diff.reshape(1)), 0);  // real pixels byte-equal
  EXPECT_EQ(cv::countNonZero(depth_diff), 0);
  cv::Mat inserted_depth;
  out.depth.copyTo(inserted_depth, mask);
  double lo, hi;
  cv::minMaxLoc(inserted_depth, &lo, &hi, nullptr, nullptr, mask);
  EXPECT_GT(hi - lo, 0.0);  // noise reached the inserted depth
  EXPECT_LT(hi, 1.05);

  rendered.depth = cv::Mat(39, 60, CV_32FC1);
  EXPECT_THROW(compositeOverReal(rendered, real_rgb, real_depth, out), std::invalid_argument);
}

/// A map whose cells are bare floor over `floor` and blocked elsewhere.
FloorMap syntheticMap(const cv::Rect2d& floor, const FloorMapOptions& options) {
  FloorMap map({-10, -10}, {10, 10}, options);
  PointGrid bare = horizontalPatch(floor.x, floor.x + floor.width, floor.y, floor.y + floor.height,
                                   0.0, options.cell / 2);
  map.addPoints(bare);
  map.finish();
  return map;
}

TEST(AugmentFloorPlanner, KeepsPeopleApartOnClearFloorAndFitsCarsOnlyWhereTheyFit) {
  FloorMapOptions map_options;
  map_options.cell = 0.1;
  const FloorMap room = syntheticMap({-3, -2, 6, 4}, map_options);
  EXPECT_TRUE(room.isClear({0, 0}));
  EXPECT_FALSE(room.isClear({-2.9, 0}));  // within the clearance of the edge
  CameraTrack camera;
  for (int k = 0; k <= 300; ++k) camera.t.push_back(k / 30.0), camera.xy.emplace_back(-2.5, 0);
  PeopleOptions people;
  people.walkers = 3;
  people.standing = 1;
  FloorPlanOptions plan;
  std::mt19937_64 rng(9);
  const auto paths = planPeople(people, room, Eigen::Vector2d::Zero(), camera, plan, rng);
  ASSERT_EQ(paths.size(), 4u);
  for (double t = 0; t <= 10; t += 0.1)
    for (size_t i = 0; i < paths.size(); ++i) {
      Eigen::Vector2d p, q;
      double h;
      paths[i].at(t, p, h);
      EXPECT_TRUE(room.isClear(p)) << i << " at t " << t;
      EXPECT_GE((p - camera.xy[0]).norm(), plan.camera_clearance);
      for (size_t j = 0; j < i; ++j) {
        paths[j].at(t, q, h);
        EXPECT_GE((p - q).norm(), plan.separation) << i << ", " << j << " at t " << t;
      }
    }
  EXPECT_GE(paths[0].length(), plan.min_walk_length);
  EXPECT_TRUE(paths[3].standing());

  CarOptions cars;
  cars.driving = 1;
  cars.parked = 1;
  EXPECT_THROW(planCars(cars, room, {0, 0}, camera, plan, rng), std::runtime_error);  // 6 x 4 m
  const FloorMap car_park = syntheticMap({-9, -6, 18, 12}, map_options);
  CameraTrack roadside{camera.t, std::vector<Eigen::Vector2d>(camera.t.size(), {0, -9.5})};
  const auto car_paths = planCars(cars, car_park, {0, 0}, roadside, plan, rng);
  ASSERT_EQ(car_paths.size(), 2u);
  EXPECT_FALSE(car_paths[0].standing());
  EXPECT_TRUE(car_paths[1].standing());
  for (double t = 0; t <= 10; t += 0.1) {
    Eigen::Vector2d p;
    double h;
    car_paths[0].at(t, p, h);
    EXPECT_TRUE(car_park.isClear(p)) << t;
  }
}

// A closet (0.9 m square, the camera far away) has no clear chord of 0.8 m: the planner walks
// the people on shorter paths or makes walkers stand, places everybody, and says what it did.
TEST(AugmentFloorPlanner, FallsBackToShorterWalksOrStandingPeopleAndSaysSo) {
  FloorMapOptions map_options;
  map_options.cell = 0.1;
  const FloorMap closet = syntheticMap({0, 0, 0.9, 0.9}, map_options);
  CameraTrack camera{{0.0}, {Eigen::Vector2d(5, 5)}};
  PeopleOptions people;  // 3 walkers, 1 standing
  std::mt19937_64 rng(1);
  std::vector<std::string> fallbacks;
  const auto paths = planPeople(people, closet, {0.45, 0.45}, camera, {}, rng, &fallbacks);
  EXPECT_EQ(paths.size(), 4u) << "everybody placed";
  ASSERT_EQ(fallbacks.size(), 1u);
  EXPECT_NE(fallbacks[0].find("no clear straight path of 0.8 m"), std::string::npos)
      << fallbacks[0];
  EXPECT_NE(fallbacks[0].find("asked for 3 and 1"), std::string::npos) << fallbacks[0];
  for (const auto& path : paths)
    for (double t = 0; t <= 10; t += 0.5) {
      Eigen::Vector2d p;
      double h;
      path.at(t, p, h);
      EXPECT_TRUE(closet.isClear(p + Eigen::Vector2d(0.45, 0.45))) << "on the clear floor, t " << t;
    }

  // A floor with room for the ini's people changes nothing and says nothing.
  const FloorMap hall = syntheticMap({0, 0, 6, 6}, map_options);
  fallbacks.clear();
  EXPECT_EQ(planPeople(people, hall, {3, 3}, camera, {}, rng, &fallbacks).size(), 4u);
  EXPECT_TRUE(fallbacks.empty());
}

// Only a region without any clear cell stops the plan.
TEST(AugmentFloorPlanner, SaysWhyWhenTheRegionHasNoClearFloor) {
  FloorMapOptions map_options;
  map_options.cell = 0.1;
  const FloorMap closet = syntheticMap({0, 0, 0.9, 0.9}, map_options);
  CameraTrack camera{{0.0}, {Eigen::Vector2d(5, 5)}};
  std::mt19937_64 rng(1);
  FloorPlanOptions far;
  far.region_radius = 0.5;
  try {
    planPeople(PeopleOptions{}, closet, {20, 20}, camera, far, rng);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no clear floor within 0.5"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace dynslam::sim
