#include <dynslam/core/Config.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/tracking/RegisterStages.h>
#include <dynslam/tracking/TrackingStage.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace dynslam;
using namespace dynslam::tracking;

namespace {

core::Frame frameAt(int k, bool fresh, float x) {
  core::Frame f;
  f.index = k;
  f.t = 100.0 + k / 30.0;
  f.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(5.0f));
  f.detections_fresh = fresh;
  if (fresh) {
    core::Detection d;
    d.box = cv::Rect2f(x, 100, 60, 180);
    d.category = "person";
    f.detections.push_back(d);
    core::ObjectMask m;
    m.detection = 0;
    m.valid = true;
    m.d_t = 2.0;
    f.object_masks.push_back(m);
  }
  return f;
}

std::string errorOf(const std::string& ini) {
  TrackingStage stage;
  try {
    stage.configure(core::IniConfig::fromText(ini, "test.ini"), "Tracking");
  } catch (const core::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TrackingStage, RegisteredAndConfiguredFromItsSection) {
  core::StageRegistry registry;
  registerStages(registry);
  auto stage = registry.create("Tracking");
  ASSERT_TRUE(dynamic_cast<TrackingStage*>(stage.get()));
  stage->configure(
      core::IniConfig::fromText("[Tracking]\nrho_min = 0.6\nmax_age = 12\nmin_hits = 4\n"
                                "meas_center_px = 4.5\naccel_depth = 0.5\n"),
      "Tracking");
  const auto& o = static_cast<TrackingStage&>(*stage).options().tracker;
  EXPECT_EQ(o.rho_min, 0.6);
  EXPECT_EQ(o.max_age, 12);
  EXPECT_EQ(o.min_hits, 4);
  EXPECT_EQ(o.noise.meas_center_px, 4.5);
  EXPECT_EQ(o.noise.accel_depth, 0.5);
  EXPECT_EQ(o.noise.meas_area_rel, BoxNoiseParams().meas_area_rel) << "defaults kept";
}

TEST(TrackingStage, EveryKeyIsDocumentedAndTyposAreErrors) {
  const auto keys = core::knownKeys(TrackingOptions());
  for (const char* key : {"rho_min",
                          "rho_min_coasting",
                          "max_age",
                          "min_hits",
                          "reset_at_border",
                          "meas_center_px",
                          "meas_area_rel",
                          "meas_depth_rel",
                          "meas_ratio",
                          "accel_center_px",
                          "accel_area_rel",
                          "accel_depth",
                          "ratio_walk",
                          "init_rate_center_px",
                          "init_rate_area_rel",
                          "init_rate_depth",
                          "reid_memory",
                          "alternative_depth",
                          "alternative_depth_tracks",
                          "depth_gate",
                          "depth_gate_frames",
                          "depth_gate_speed",
                          "innovation_gate",
                          "reid_at_track_depth",
                          "descriptor_own_surface",
                          "identity_check",
                          "identity_repair",
                          "revival_takes_identity"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  EXPECT_EQ(keys.size(), 29u);
  EXPECT_NE(errorOf("[Tracking]\nrho_mn = 0.5\n").find("rho_mn"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nrho_min = 1.5\n").find("rho_min"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nrho_min_coasting = -0.1\n").find("rho_min_coasting"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nmin_hits = 0\n").find("min_hits"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nrevival_takes_identity = -1\n").find("revival_takes_identity"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nratio_walk = 0\n").find("ratio_walk"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nreid_memory = -1\n").find("reid_memory"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nidentity_repair = -1\n").find("identity_repair"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\ndepth_gate = 1.5\n").find("depth_gate"), std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\ndepth_gate_frames = 0\n").find("depth_gate_frames"),
            std::string::npos)
      << "0 frames would hold nothing";
  EXPECT_NE(errorOf("[Tracking]\nidentity_check = 2\n").find("identity_check"), std::string::npos)
      << "two distances of at most 1 never differ by 2";
  EXPECT_NE(errorOf("[Tracking]\ndepth_gate_speed = -1\n").find("depth_gate_speed"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nreid_at_track_depth = 2\n").find("reid_at_track_depth"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\ninnovation_gate = -1\n").find("innovation_gate"),
            std::string::npos);
  EXPECT_EQ(errorOf("[Tracking]\n"), "");
}

TEST(TrackingStage, ASettingWithoutTheOneItActsThroughIsAnErrorNamingBoth) {
  const std::string reid = "reid_max_distance = 0.7\nreid_memory = 10\n";
  const std::string msg = errorOf("[Tracking]\n" + reid + "identity_repair = 10\n");
  EXPECT_NE(msg.find("identity_repair"), std::string::npos) << msg;
  EXPECT_NE(msg.find("identity_check"), std::string::npos) << msg;
  EXPECT_NE(msg.find("test.ini"), std::string::npos) << msg;
  EXPECT_EQ(errorOf("[Tracking]\n" + reid + "identity_check = 0.05\nidentity_repair = 10\n"), "");
  const std::string noReid = "reid_max_distance = 0\nreid_memory = 0\n";
  EXPECT_NE(errorOf("[Tracking]\n" + noReid + "identity_check = 0.05\n").find("reid_max_distance"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\nalternative_depth = false\nalternative_depth_tracks = true\n")
                .find("alternative_depth"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\ndepth_gate = 0\ndepth_gate_speed = 1.5\n").find("depth_gate > 0"),
            std::string::npos);
  EXPECT_NE(errorOf("[Tracking]\ndepth_gate = 0\ndepth_gate_frames = 3\n").find("depth_gate > 0"),
            std::string::npos);
  // rho_min_coasting acts only below rho_min (a second round at a lower threshold).
  EXPECT_NE(errorOf("[Tracking]\nrho_min_coasting = 0.6\n").find("rho_min > rho_min_coasting"),
            std::string::npos);
  EXPECT_EQ(errorOf("[Tracking]\nrho_min_coasting = 0.3\n"), "");
}

TEST(TrackingStage, FramesWithoutFreshDetectionsCarryPredictedBoxes) {
  TrackingStage stage;
  stage.configure(core::IniConfig::fromText("[Tracking]\n"), "Tracking");
  for (int k = 0; k < 20; ++k) {  // 3 px per frame
    core::Frame f = frameAt(k, true, 100 + 3.0f * k);
    stage.process(f);
    ASSERT_EQ(f.tracks.size(), 1u);
    EXPECT_EQ(f.tracks[0].detection, 0);
    EXPECT_NEAR(f.tracks[0].depth, 2.0, 1e-6) << "the segmentation's d_t, not the 5 m image";
  }
  // The detector thread was busy for two frames: the tracker predicts on its own.
  for (int k = 20; k < 22; ++k) {
    core::Frame f = frameAt(k, false, 0);
    stage.process(f);
    ASSERT_EQ(f.tracks.size(), 1u);
    const core::Track& t = f.tracks[0];
    EXPECT_EQ(t.detection, -1);
    EXPECT_EQ(t.misses, 0) << "not a detector frame, not a miss";
    EXPECT_EQ(t.state, core::TrackState::Confirmed);
    EXPECT_NEAR(t.box.x, 100 + 3.0 * k, 1.0);
  }
  core::Frame f = frameAt(22, true, 166);
  stage.process(f);
  ASSERT_EQ(f.tracks.size(), 1u);
  EXPECT_EQ(f.tracks[0].id, 1);
  EXPECT_EQ(f.tracks[0].detection, 0);
}

TEST(TrackingStage, WithoutMasksTheDepthComesFromTheBox) {
  TrackingStage stage;
  stage.configure(core::IniConfig::fromText("[Tracking]\n"), "Tracking");
  core::Frame f = frameAt(0, true, 100);
  f.object_masks.clear();
  stage.process(f);
  ASSERT_EQ(f.tracks.size(), 1u);
  EXPECT_NEAR(f.tracks[0].depth, 5.0, 1e-6);
}
