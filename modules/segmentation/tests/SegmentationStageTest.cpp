#include <dynslam/core/Config.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/segmentation/RegisterStages.h>
#include <dynslam/segmentation/SegmentationStage.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;

TEST(SegmentationStage, IsRegisteredAndReadsItsKeys) {
  core::StageRegistry registry;
  segmentation::registerStages(registry);
  auto stage = registry.create("Segmentation");
  stage->configure(core::IniConfig::fromText("[Segmentation]\nm = 36\nn = 25\ne_person = 0.4\n"
                                             "e_car = 2.5\nmin_valid_fraction = 0.5\n"
                                             "max_height_person = 2.2\nexpected_depth_band = 0.1\n"
                                             "retry_taken_surface = true\n"
                                             "joint_occluders = true\n"
                                             "object_cluster = occluder_aware\n"
                                             "boxes = tracked_detections\n"),
                   "Segmentation");
  const auto& p = dynamic_cast<segmentation::SegmentationStage&>(*stage).options().params;
  EXPECT_EQ(p.m, 36);
  EXPECT_EQ(p.n, 25);
  EXPECT_EQ(p.e_person, 0.4);
  EXPECT_EQ(p.e_car, 2.5);
  EXPECT_EQ(p.min_valid_fraction, 0.5);
  EXPECT_EQ(p.max_height_person, 2.2);
  EXPECT_EQ(p.expected_depth_band, 0.1);
  EXPECT_TRUE(p.retry_taken_surface);
  EXPECT_TRUE(p.joint_occluders);
}

TEST(SegmentationStage, DefaultsAreTheShippedOnesAndBadKeysOrValuesAreConfigErrors) {
  segmentation::SegmentationStage stage;
  stage.configure(core::IniConfig::fromText(""), "Segmentation");
  const auto& p = stage.options().params;
  EXPECT_EQ(p.m, 64);
  EXPECT_EQ(p.n, 64);
  EXPECT_EQ(p.e_person, 0.5);
  EXPECT_EQ(p.e_car, 3.0);
  // params/sim_vio.ini's [Segmentation], not the method (methodParams()).
  EXPECT_EQ(p.object_cluster, segmentation::ObjectCluster::OccluderAware);
  EXPECT_EQ(p.overlap_rule, segmentation::OverlapRule::Connected);
  EXPECT_EQ(p.object_depth, segmentation::ObjectDepth::MaskMedian);
  EXPECT_EQ(p.max_height_person, 2.2);
  EXPECT_TRUE(p.joint_occluders);
  EXPECT_FALSE(p.retry_taken_surface) << "a per-instance setting";
  EXPECT_EQ(p.expected_depth_band, 0.0) << "a per-instance setting";
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[S]\ne_pedestrian = 1\n"), "S"),
               core::ConfigError);
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[S]\nobject_cluster = near\n"), "S"),
               core::ConfigError)
      << "names the section and the file";
  stage.configure(
      core::IniConfig::fromText("[S]\nobject_cluster = larger\njoint_occluders = false\n"), "S");
  EXPECT_EQ(stage.options().params.object_cluster, segmentation::ObjectCluster::Larger);
  stage.configure(core::IniConfig::fromText("[S]\nobject_depth = cluster_mean\n"), "S");
  EXPECT_EQ(stage.options().params.object_depth, segmentation::ObjectDepth::ClusterMean);
  EXPECT_THROW(stage.configure(core::IniConfig::fromText("[S]\nobject_depth = mean\n"), "S"),
               core::ConfigError);
  try {
    stage.configure(core::IniConfig::fromText("[S]\nm = 1\n", "x.ini"), "S");
    FAIL() << "m = 1 accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("m = 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("x.ini"), std::string::npos) << e.what();
  }
  for (const char* bad : {"max_height_person = -2", "e_car = 0", "min_valid_fraction = 1.5",
                          "min_valid_fraction = 0", "n = 0", "m = 2.5", "e_person = 0.5 m"})
    EXPECT_THROW(stage.configure(core::IniConfig::fromText(std::string("[S]\n") + bad), "S"),
                 core::ConfigError)
        << bad;
}

// A setting that acts only through another is refused alone, naming both keys; with the other
// it is taken. joint_occluders is on by default, so the method's far cluster turns it off.
TEST(SegmentationStage, SettingsThatActOnlyThroughAnotherAreRefusedAlone) {
  struct Case {
    const char *setting, *without, *needed;
  };
  const Case cases[] = {
      {"retry_taken_surface = true", "object_cluster = far\njoint_occluders = false",
       "object_cluster = occluder_aware"},
      {"joint_occluders = true", "object_cluster = far", "object_cluster = occluder_aware"},
      {"expected_depth_band = 0.1", "boxes = detections", "boxes = tracked_detections"},
      {"max_track_misses = 3", "boxes = detections", "boxes = predicted_tracks"}};
  for (const auto& c : cases) {
    segmentation::SegmentationStage stage;
    const std::string setting = c.setting;
    try {
      stage.configure(
          core::IniConfig::fromText("[S]\n" + setting + "\n" + c.without + "\n", "s.ini"), "S");
      FAIL() << setting << " accepted with " << c.without;
    } catch (const core::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(setting.substr(0, setting.find(' '))), std::string::npos) << what;
      EXPECT_NE(what.find(c.needed), std::string::npos) << what;
      EXPECT_NE(what.find("s.ini"), std::string::npos) << what;
    }
    stage.configure(core::IniConfig::fromText("[S]\n" + setting + "\n" + c.needed + "\n"), "S");
  }
}

TEST(SegmentationStage, WritesOneMaskPerDetectionInOrder) {
  segmentation::SegmentationStage stage;
  stage.configure(core::IniConfig::fromText(""), "Segmentation");
  core::Frame frame;
  frame.depth = cv::Mat(120, 160, CV_32FC1, cv::Scalar(5.0f));
  frame.depth(cv::Rect(20, 30, 30, 90)).setTo(2.0f);
  frame.depth(cv::Rect(100, 30, 30, 90)).setTo(3.0f);
  frame.detections.resize(3);
  frame.detections[0].box = cv::Rect2f(100, 20, 30, 100);
  frame.detections[1].box = cv::Rect2f(20, 20, 30, 100);
  frame.detections[2].box = cv::Rect2f(140, 0, 20, 20);
  for (auto& d : frame.detections) d.category = "person";
  frame.depth(cv::Rect(140, 0, 20, 20)).setTo(0);
  stage.process(frame);
  ASSERT_EQ(frame.object_masks.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(frame.object_masks[i].detection, i);
  EXPECT_DOUBLE_EQ(frame.object_masks[0].d_t, 3.0);
  EXPECT_DOUBLE_EQ(frame.object_masks[1].d_t, 2.0);
  EXPECT_FALSE(frame.object_masks[2].valid) << "no depth in its box";

  core::Frame noDepth;
  noDepth.detections.resize(1);
  EXPECT_THROW(stage.process(noDepth), std::runtime_error);
  noDepth.detections.clear();
  stage.process(noDepth);
  EXPECT_TRUE(noDepth.object_masks.empty());
}

TEST(SegmentationStage, TrackedDetectionsTakeTheClusterOfTheirTracksDepth) {
  // A walker 2 m away with the wall (5 m) between its legs: occluder_aware takes the walker.
  // A track that took the detection at 5 m (Tracking.alternative_depth) makes the mask the
  // wall's; a track at 2.1 m keeps the walker's; the masks keep their tracks.
  core::Frame frame;
  frame.depth = cv::Mat(240, 320, CV_32FC1, cv::Scalar(5.0f));
  const cv::Rect box(100, 20, 60, 200);
  frame.depth(box).setTo(2.0f);
  frame.depth(cv::Rect(124, 120, 12, 100)).setTo(5.0f);
  frame.detections.resize(1);
  frame.detections[0].box = cv::Rect2f(box);
  frame.detections[0].category = "person";
  frame.tracks.resize(2);
  frame.tracks[1].detection = 0;
  segmentation::SegmentationStage stage;
  stage.configure(core::IniConfig::fromText("[R]\nboxes = tracked_detections\n"
                                            "object_cluster = occluder_aware\n"),
                  "R");
  for (const auto& [trackDepth, expected] : {std::pair{5.0, 5.0}, std::pair{2.1, 2.0}}) {
    frame.tracks[1].depth = trackDepth;
    frame.object_masks.clear();
    stage.process(frame);
    ASSERT_EQ(frame.object_masks.size(), 1u);
    EXPECT_NEAR(frame.object_masks[0].d_t, expected, 1e-6) << trackDepth;
    EXPECT_EQ(frame.object_masks[0].track, 1);
  }
}

TEST(SegmentationStage, PredictedBoxesSegmentTheCoastingTracksUpToMaxTrackMisses) {
  // Three confirmed tracks: one matched this frame (its detection's mask is made before
  // Tracking), two coasting for 2 and 30 frames. The walker of the second has left the image
  // long ago: its predicted box would take the wall.
  core::Frame frame;
  frame.detections_fresh = true;
  frame.depth = cv::Mat(120, 160, CV_32FC1, cv::Scalar(5.0f));
  frame.depth(cv::Rect(20, 30, 30, 90)).setTo(2.0f);
  frame.tracks.resize(3);
  for (int i = 0; i < 3; ++i) {
    frame.tracks[i].id = 10 + i;
    frame.tracks[i].state = core::TrackState::Confirmed;
    frame.tracks[i].category = "person";
  }
  frame.tracks[0].detection = 0;
  frame.tracks[0].box = cv::Rect2f(20, 20, 30, 100);
  frame.tracks[1].misses = 2;
  frame.tracks[1].box = cv::Rect2f(20, 20, 30, 100);
  frame.tracks[2].misses = 30;
  frame.tracks[2].box = cv::Rect2f(100, 20, 30, 100);
  const auto masksOf = [&](const std::string& ini) {
    segmentation::SegmentationStage stage;
    stage.configure(core::IniConfig::fromText("[P]\nboxes = predicted_tracks\n" + ini), "P");
    core::Frame f = frame;
    stage.process(f);
    std::vector<int> tracks;
    for (const auto& m : f.object_masks) tracks.push_back(m.track);
    return tracks;
  };
  EXPECT_EQ(masksOf(""), (std::vector<int>{1, 2})) << "every coasting track (the default)";
  EXPECT_EQ(masksOf("max_track_misses = 3\n"), (std::vector<int>{1}));
  segmentation::SegmentationStage stage;
  try {
    stage.configure(core::IniConfig::fromText("[P]\nmax_track_misses = -1\n"), "P");
    FAIL() << "a negative max_track_misses accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("max_track_misses"), std::string::npos) << e.what();
  }
}
