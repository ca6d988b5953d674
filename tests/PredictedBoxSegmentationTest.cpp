// Real-time mode's stand-in for detections (method.md section 2): on frames the detector thread
// skipped, the second Segmentation instance segments the tracker's predicted boxes, and every
// mask names its track, so later stages can tell which object a pixel belongs to on every frame.
#include <dynslam/core/Config.h>
#include <dynslam/core/Pipeline.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/segmentation/RegisterStages.h>
#include <dynslam/tracking/RegisterStages.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;

namespace {

constexpr const char* kRealtimeIni =
    "[pipeline]\n"
    "stages = Segmentation, Tracking, Segmentation:PredictedBoxes\n"
    "[Tracking]\n"
    "min_hits = 2\n"
    "[PredictedBoxes]\n"
    "boxes = predicted_tracks\n";

// A person 2 m away in front of a wall 5 m away, walking right at 2 px per frame; the detector
// reports it on every third frame only (a detector thread at a third of the camera rate).
cv::Rect personAt(int k) { return cv::Rect(100 + 2 * k, 120, 50, 160); }

core::Frame frameAt(int k) {
  core::Frame f;
  f.index = k;
  f.t = 10.0 + k / 30.0;
  f.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(5.0f));
  f.depth(personAt(k)).setTo(2.0f);
  f.detections_fresh = k % 3 == 0;
  if (f.detections_fresh) {
    core::Detection d;
    d.box = cv::Rect2f(personAt(k));
    d.category = "person";
    f.detections.push_back(d);
  }
  return f;
}

double maskIoU(const core::ObjectMask& m, const cv::Rect& truth) {
  cv::Mat full = cv::Mat::zeros(480, 640, CV_8UC1);
  m.mask.copyTo(full(m.roi));
  cv::Mat expected = cv::Mat::zeros(480, 640, CV_8UC1);
  expected(truth).setTo(255);
  const double inter = cv::countNonZero(full & expected);
  const double uni = cv::countNonZero(full | expected);
  return uni > 0 ? inter / uni : 0.0;
}

}  // namespace

TEST(PredictedBoxSegmentation, SkippedFramesGetMasksOfThePredictedBoxes) {
  core::StageRegistry registry;
  segmentation::registerStages(registry);
  tracking::registerStages(registry);
  core::Pipeline pipeline(core::IniConfig::fromText(kRealtimeIni, "realtime.ini"), registry);

  int skippedWithMask = 0;
  for (int k = 0; k < 30; ++k) {
    core::Frame f = frameAt(k);
    pipeline.process(f);
    const bool confirmed = k >= 3;  // two detector frames (0 and 3) confirm the track
    if (f.detections_fresh) {
      ASSERT_EQ(f.object_masks.size(), 1u) << "frame " << k;
      EXPECT_EQ(f.object_masks[0].detection, 0);
      ASSERT_EQ(f.object_masks[0].track, 0) << "the mask names the track that took it";
      EXPECT_EQ(f.tracks[0].detection, 0);
      continue;
    }
    if (!confirmed) {
      EXPECT_TRUE(f.object_masks.empty()) << "a tentative track is not segmented, frame " << k;
      continue;
    }
    ASSERT_EQ(f.object_masks.size(), 1u) << "frame " << k;
    const auto& m = f.object_masks[0];
    EXPECT_EQ(m.detection, -1);
    ASSERT_EQ(m.track, 0);
    EXPECT_EQ(f.tracks[0].id, 1);
    EXPECT_NEAR(m.d_t, 2.0, 1e-6);
    if (k >= 9) {  // the filter has learned the walking speed from three detector frames
      EXPECT_GT(maskIoU(m, personAt(k)), 0.9) << "frame " << k;
    }
    ++skippedWithMask;
  }
  EXPECT_EQ(skippedWithMask, 18);
}

TEST(PredictedBoxSegmentation, UnknownBoxesValueIsAConfigErrorNamingIt) {
  core::StageRegistry registry;
  segmentation::registerStages(registry);
  try {
    core::Pipeline pipeline(
        core::IniConfig::fromText("[pipeline]\nstages = Segmentation\n[Segmentation]\n"
                                  "boxes = tracks\n",
                                  "bad.ini"),
        registry);
    FAIL() << "boxes = tracks accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("boxes = 'tracks'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.ini"), std::string::npos) << e.what();
  }
}

TEST(PredictedBoxSegmentation, AnObjectTheDetectorMissedGetsItsPredictedMask) {
  core::StageRegistry registry;
  segmentation::registerStages(registry);
  tracking::registerStages(registry);
  core::Pipeline pipeline(core::IniConfig::fromText(kRealtimeIni, "realtime.ini"), registry);
  for (int k = 0; k < 12; ++k) {  // detector on every frame (fresh), except a miss at 10
    core::Frame f = frameAt(k);
    f.detections_fresh = true;
    if (f.detections.empty() || k == 10) {
      f.detections.clear();
      if (k != 10) {
        core::Detection d;
        d.box = cv::Rect2f(personAt(k));
        d.category = "person";
        f.detections.push_back(d);
      }
    }
    pipeline.process(f);
    if (k == 10) {
      ASSERT_EQ(f.object_masks.size(), 1u) << "the coasting track's predicted box";
      EXPECT_EQ(f.object_masks[0].detection, -1);
      EXPECT_EQ(f.object_masks[0].track, 0);
      EXPECT_GT(maskIoU(f.object_masks[0], personAt(k)), 0.9);
    } else if (k > 0) {
      ASSERT_EQ(f.object_masks.size(), 1u) << "frame " << k << ": the detection's mask only";
      EXPECT_EQ(f.object_masks[0].detection, 0);
    }
  }
}
