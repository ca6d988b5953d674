// OpenCV's HOG people detector finds walkers in vtest.avi with no model file; bad settings are
// errors.
#include "OpenCvDocImages.h"

#include <dynslam/detection/HogPeopleDetector.h>

#include <gtest/gtest.h>

namespace det = dynslam::detection;

TEST(HogPeopleDetector, FindsWalkersInSampledVtestFrames) {
  DYNSLAM_REQUIRE_OPENCV_DOC(video, "vtest.avi");
  const auto frames = det::testing::vtestFrames({0, 300, 600});
  ASSERT_EQ(frames.size(), 3u) << "cannot decode " << video;
  det::HogPeopleDetector detector({}, det::ClassMap());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    dynslam::core::Frame frame;
    frame.rgb = frames[i];
    const auto found = detector.detect(frame);
    int people = 0;
    for (const auto& d : found) {
      EXPECT_EQ(d.category, "person");
      EXPECT_GT(d.score, 0.5f);  // logistic of a margin above hit_threshold 0
      people += d.box.height > 90 && d.box.height < 200;  // walkers are about 100-150 px
    }
    EXPECT_GE(people, 3) << "sample " << i;
  }
}

TEST(HogPeopleDetector, ReportsNothingWhenPersonIsUnmappedAndRejectsBadSettings) {
  dynslam::core::Frame frame;
  frame.rgb = cv::Mat(256, 256, CV_8UC3, cv::Scalar(0, 0, 0));
  det::HogPeopleDetector cars_only({}, det::ClassMap::parse("car:car:rigid"));
  EXPECT_TRUE(cars_only.detect(frame).empty());
  frame.rgb.release();
  det::HogPeopleDetector detector({}, det::ClassMap());
  EXPECT_THROW(detector.detect(frame), det::DetectorError);

  det::HogPeopleDetectorSettings bad;
  bad.win_stride = 12;
  EXPECT_THROW(det::HogPeopleDetector(bad, det::ClassMap()), det::DetectorError)
      << "not a multiple of the 8-pixel cell";
}
