// Grid-uniform Shi-Tomasi corners: spread over the textured cells, none on a bare (noisy)
// wall, never closer than the spacing to each other or to the tracked points.
#include <dynslam/frontend/GridCornerDetector.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <set>

using namespace dynslam::frontend;

namespace {

/// Left half: blurred random texture, except one sharper, stronger 120x120 square; right half: a
/// flat grey wall with sensor noise (sigma 3).
cv::Mat testImage() {
  cv::Mat img(480, 640, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(5);
  cv::Mat weak(480, 320, CV_8UC1);
  rng.fill(weak, cv::RNG::UNIFORM, 40, 216);
  cv::GaussianBlur(weak, weak, cv::Size(0, 0), 1.0);
  weak.copyTo(img(cv::Rect(0, 0, 320, 480)));
  cv::Mat strong(120, 120, CV_8UC1);
  rng.fill(strong, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(strong, strong, cv::Size(0, 0), 1.5);
  strong.copyTo(img(cv::Rect(40, 40, 120, 120)));
  cv::Mat noise(480, 320, CV_16SC1);
  rng.fill(noise, cv::RNG::NORMAL, 0, 3);
  cv::Mat right;
  img(cv::Rect(320, 0, 320, 480)).convertTo(right, CV_16SC1);
  right += noise;
  right.convertTo(img(cv::Rect(320, 0, 320, 480)), CV_8UC1);
  return img;
}

}  // namespace

TEST(GridCornerDetector, SpreadOverTexturedCellsNoneOnABareWall) {
  const cv::Mat img = testImage();
  for (int level : {0, 1}) {
    GridCornerParams p;
    p.level = level;
    // The floor is in the scored image's units: at full resolution the wall's noise reaches
    // 4.3e-4 (pyrDown halves its sigma: 5.8e-5 at level 1), the texture's corners 1e-3 to 1e-2.
    if (level == 0) p.min_eigenvalue = 1e-3;
    cv::Mat scored = img;
    if (level == 1) cv::pyrDown(img, scored);
    cv::Mat free = freeSpaceMask(img.size(), {}, p);
    int computed = 0;
    const auto corners = detectGridCorners(scored, free, {}, 60, p, &computed);
    ASSERT_EQ(corners.size(), 60u) << "level " << level;
    std::set<int> cells;
    int inStrong = 0;
    for (const auto& c : corners) {
      // (a corner may sit on the texture's edge at x = 320, seen through the 3x3 block)
      EXPECT_LT(c.x, 326) << "level " << level << ": a corner on the bare wall at " << c;
      EXPECT_GE(c.x, p.border_px);
      EXPECT_GE(c.y, p.border_px);
      inStrong += cv::Rect(40, 40, 120, 120).contains(cv::Point(c));
      cells.insert(int(c.y * p.grid_rows / 480) * p.grid_cols + int(c.x * p.grid_cols / 640));
    }
    // 24 textured cells: 60 corners fill all of them, 2-3 each, the strong square takes its
    // share (its ~4 cells), not all.
    EXPECT_GE(cells.size(), 24u) << "level " << level;
    EXPECT_LE(cells.size(), 25u) << "level " << level;
    EXPECT_LT(inStrong, 15) << "level " << level;
    for (size_t a = 0; a < corners.size(); ++a)
      for (size_t b = a + 1; b < corners.size(); ++b)
        EXPECT_GE(cv::norm(corners[a] - corners[b]), p.min_distance_px - 1.5);
  }
}

TEST(GridCornerDetector, KeepsAwayFromTrackedPointsAndFillsTheEmptiestCellsFirst) {
  const cv::Mat img = testImage();
  GridCornerParams p;
  p.level = 0;
  // Three tracked points in the cell at (0, 0); the others are empty.
  const std::vector<cv::Point2f> tracked{{30, 30}, {60, 50}, {40, 70}};
  cv::Mat free = freeSpaceMask(img.size(), tracked, p);
  const auto corners = detectGridCorners(img, free, tracked, 23, p);
  ASSERT_EQ(corners.size(), 23u);
  for (const auto& c : corners) {
    for (const auto& t : tracked) EXPECT_GE(cv::norm(c - t), p.min_distance_px - 1.5);
    // 23 corners for 23 empty textured cells: the occupied cell gets none.
    EXPECT_FALSE(c.x < 80 && c.y < 80) << c;
  }
  // The mask now holds the new corners too.
  for (const auto& c : corners) EXPECT_EQ(free.at<uint8_t>(cv::Point(c)), 0);
}

TEST(GridCornerDetector, ClaimIfFreeKeepsTheFirstOfTwoCloseTracks) {
  GridCornerParams p;
  cv::Mat free = freeSpaceMask(cv::Size(100, 100), {}, p);
  EXPECT_TRUE(claimIfFree(free, {50, 50}, p));
  EXPECT_FALSE(claimIfFree(free, {60, 55}, p)) << "11 px from a longer track";
  EXPECT_TRUE(claimIfFree(free, {50, 75}, p)) << "25 px away";
  EXPECT_FALSE(claimIfFree(free, {-1, 5}, p)) << "outside the image";
}
