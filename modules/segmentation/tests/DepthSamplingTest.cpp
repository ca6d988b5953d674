#include <dynslam/segmentation/DepthSampling.h>

#include <gtest/gtest.h>

using namespace dynslam::segmentation;

TEST(DepthSampling, GridSpacingIsEvenAlongBothAxes) {
  EXPECT_EQ(gridShape(64, 40, 40), cv::Size(8, 8));
  EXPECT_EQ(gridShape(64, 40, 100), cv::Size(5, 13)) << "a person's box: more rows";
  EXPECT_EQ(gridShape(64, 60, 30), cv::Size(11, 6));
  EXPECT_EQ(gridShape(64, 1, 1000), cv::Size(1, 64));
  EXPECT_EQ(gridShape(1, 50, 20), cv::Size(1, 1));
}

TEST(DepthSampling, SamplesCellCentresAndSkipsInvalidDepth) {
  // Depth = column index + 1, so a sample's value tells which column it came from.
  cv::Mat depth(10, 20, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) depth.at<float>(v, u) = u + 1.0f;
  depth.col(6).setTo(0);  // no depth in one column
  std::vector<float> z;
  const int points = sampleGrid(depth, cv::Rect2d(4, 2, 8, 4), 8, z);
  ASSERT_EQ(points, 8);  // 4 x 2 grid, cell width 2: columns 5, 7, 9, 11
  ASSERT_EQ(z.size(), 8u);
  EXPECT_EQ(z[0], 6.0f);
  EXPECT_EQ(z[1], 8.0f);
  EXPECT_EQ(z[3], 12.0f);
  z.clear();
  // 3 x 3 grid, cell width 4/3: columns 4, 6 and 7.
  EXPECT_EQ(sampleGrid(depth, cv::Rect2d(4, 2, 4, 4), 8, z), 9);
  EXPECT_EQ(z.size(), 6u) << "column 6 has no depth";
}

TEST(DepthSampling, ThreeSigmaMeanDropsAFarOutlier) {
  std::vector<float> v(20, 4.0f);
  v.push_back(40.0f);  // about 4.5 sigma from the mean of all 21
  EXPECT_DOUBLE_EQ(threeSigmaMean(v), 4.0);
  std::vector<float> twoLevels = {2, 2, 2, 5, 5, 5};  // nothing beyond 3 sigma
  EXPECT_DOUBLE_EQ(threeSigmaMean(twoLevels), 3.5);
  EXPECT_EQ(threeSigmaMean({}), 0.0);
}
