// writeBarChartPng: the bars read back from the PNG stand in the order of the groups and
// series, their heights follow the values, a missing value draws no bar, and bad input is
// refused with an error that says what is wrong.
#include <dynslam/evaluation/EvaluationError.h>
#include <dynslam/evaluation/Plot.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace dynslam::evaluation {
namespace {

struct Bar {
  cv::Rect rect;
  cv::Vec3b colour;
};

/// The bars of a chart: saturated regions (grid, text and frame are grey or black) taller
/// than the legend's swatches, left to right.
std::vector<Bar> barsOf(const cv::Mat& img) {
  cv::Mat saturated(img.size(), CV_8UC1);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      saturated.at<uint8_t>(y, x) =
          std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 60 ? 255 : 0;
    }
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(saturated, labels, stats, centroids);
  std::vector<Bar> bars;
  for (int i = 1; i < n; ++i) {
    const cv::Rect r(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                     stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
    if (r.height > 20)
      bars.push_back({r, img.at<cv::Vec3b>(r.y + r.height / 2, r.x + r.width / 2)});
  }
  std::sort(bars.begin(), bars.end(),
            [](const Bar& a, const Bar& b) { return a.rect.x < b.rect.x; });
  return bars;
}

BarChartInput threeScenarios() {
  BarChartInput in;
  in.title = "APE RMSE per scenario";
  in.groups = {"indoor_people_high", "market_crowd_high", "outdoor_street_high"};
  in.series = {"none", "remove", "full"};
  in.values = {{0.40, 0.10, 0.20}, {0.30, 0.15, 0.05 * 3}, {0.25, 0.35, 0.10}};
  in.value_label = "APE RMSE (m)";
  return in;
}

TEST(BarChart, BarHeightsFollowTheValuesInGroupAndSeriesOrder) {
  const BarChartInput in = threeScenarios();
  const std::string png = testing::scratchDir() + "/bars.png";
  writeBarChartPng(png, in);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  const auto bars = barsOf(img);
  ASSERT_EQ(bars.size(), 9u);
  // All bars stand on one baseline; the pixels per metre are the same for every bar.
  const double perMetre = bars[0].rect.height / in.values[0][0];
  for (size_t i = 0; i < bars.size(); ++i) {
    const double v = in.values[i / 3][i % 3];
    EXPECT_EQ(bars[i].rect.br().y, bars[0].rect.br().y) << "bar " << i;
    EXPECT_NEAR(bars[i].rect.height, v * perMetre, 2.0) << "bar " << i << " (" << v << ")";
    EXPECT_EQ(bars[i].colour, bars[i % 3].colour) << "bar " << i << ": the colour of its series";
  }
  EXPECT_NE(bars[0].colour, bars[1].colour);
  EXPECT_NE(bars[1].colour, bars[2].colour);
  EXPECT_LT(bars[2].rect.x, bars[3].rect.x - 10) << "a gap between groups";
}

TEST(BarChart, AMissingValueDrawsNoBar) {
  BarChartInput in = threeScenarios();
  in.values[1][2] = std::numeric_limits<double>::quiet_NaN();
  const std::string png = testing::scratchDir() + "/bars.png";
  writeBarChartPng(png, in);
  const auto bars = barsOf(cv::imread(png, cv::IMREAD_COLOR));
  ASSERT_EQ(bars.size(), 8u);
  EXPECT_EQ(bars[5].colour, bars[0].colour) << "after the gap: the next group's first bar";
}

TEST(BarChart, RefusesValuesThatDoNotMatchTheGroupsAndSeries) {
  const std::string png = testing::scratchDir() + "/bars.png";
  const auto message = [&](const BarChartInput& in) {
    try {
      writeBarChartPng(png, in);
    } catch (const EvaluationError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  BarChartInput in = threeScenarios();
  in.values[2].pop_back();
  EXPECT_NE(message(in).find("group 'outdoor_street_high' has 2 values for 3 series"),
            std::string::npos)
      << message(in);
  in = threeScenarios();
  in.values.pop_back();
  EXPECT_NE(message(in).find("2 rows of values for 3 groups"), std::string::npos) << message(in);
  in = threeScenarios();
  in.values[0][1] = -1;
  EXPECT_NE(message(in).find("negative"), std::string::npos) << message(in);
  in = threeScenarios();
  in.series.clear();
  EXPECT_NE(message(in).find("no group or no series"), std::string::npos) << message(in);
}

}  // namespace
}  // namespace dynslam::evaluation
