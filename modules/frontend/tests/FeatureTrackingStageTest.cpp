// The FeatureTracking stage: registered by name, configured from [FeatureTracking] with every
// key documented, clear errors naming a bad key, features written to the frame.
#include "MethodSettings.h"

#include <dynslam/core/Config.h>
#include <dynslam/core/StageRegistry.h>
#include <dynslam/frontend/FeatureTrackingStage.h>
#include <dynslam/frontend/RegisterStages.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <sstream>

using namespace dynslam;
using namespace dynslam::frontend;

namespace {

std::string errorOf(const std::string& ini) {
  FeatureTrackingStage stage;
  try {
    stage.configure(core::IniConfig::fromText(ini, "test.ini"), "FeatureTracking");
  } catch (const core::ConfigError& e) {
    return e.what();
  }
  return "";
}

/// [FeatureTracking] with the method's settings (MethodSettings.h), then the lines of `ini`
/// (key = value) over them.
core::IniConfig methodTrackingWith(const std::string& ini) {
  auto cfg = core::IniConfig::fromText(
      std::string("[FeatureTracking]\n") + frontend::testing::kMethodTrackingIni, "test.ini");
  std::istringstream lines(ini);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) cfg.applyOverride("FeatureTracking." + line);
  return cfg;
}

/// A textured image shifted by `shift` pixels: something to track.
core::Frame texturedFrame(size_t index, int shift) {
  cv::Mat texture(480 + 40, 640 + 40, CV_8UC3);
  cv::RNG rng(3);
  rng.fill(texture, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(texture, texture, cv::Size(0, 0), 2.5);
  core::Frame f;
  f.index = index;
  f.t = index / 30.0;
  f.rgb = texture(cv::Rect(20 + shift, 20, 640, 480)).clone();
  f.depth = cv::Mat(480, 640, CV_32FC1, cv::Scalar(2.0f));
  f.intrinsics = {525, 525, 319.5, 239.5, 640, 480};
  return f;
}

}  // namespace

TEST(FeatureTrackingStage, RegisteredAndConfiguredFromItsSection) {
  core::StageRegistry registry;
  registerStages(registry);
  auto stage = registry.create("FeatureTracking");
  ASSERT_TRUE(dynamic_cast<FeatureTrackingStage*>(stage.get()));
  stage->configure(core::IniConfig::fromText("[FeatureTracking]\nmax_features = 80\n"
                                             "min_distance_px = 30\nflow_init = none\n"
                                             "fundamental_ransac = false\n"),
                   "FeatureTracking");
  const auto& o = static_cast<FeatureTrackingStage&>(*stage).options().tracker;
  EXPECT_EQ(o.max_features, 80);
  EXPECT_EQ(o.corners.min_distance_px, 30);
  EXPECT_EQ(o.flow_init, FlowInit::None);
  EXPECT_FALSE(o.fundamental_ransac);
}

TEST(FeatureTrackingStage, EveryKeyIsWrittenWithAComment) {
  FeatureTrackingOptions options;
  mrpt::config::CConfigFileMemory ini;
  options.saveToConfigFile(ini, "FeatureTracking");
  const auto keys = core::knownKeys(options);
  EXPECT_EQ(keys.size(), 25u);
  const std::string text = ini.getContent();
  std::istringstream lines(text);
  size_t commented = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto key = line.substr(0, line.find_first_of(" ="));
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) continue;
    EXPECT_NE(line.find("//"), std::string::npos) << key;
    ++commented;
  }
  EXPECT_EQ(commented, keys.size());
  // What it writes, it reads back (strictly).
  FeatureTrackingStage stage;
  EXPECT_NO_THROW(stage.configure(core::IniConfig::fromText(text), "FeatureTracking"));
}

TEST(FeatureTrackingStage, BadInputIsAnErrorNamingTheKey) {
  EXPECT_NE(errorOf("[FeatureTracking]\nmax_feature = 10\n").find("max_feature"),
            std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\nmax_features = 0\n").find("max_features = 0"),
            std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\nklt_window_px = 20\n").find("klt_window_px"),
            std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\nflow_init = imu\n").find("flow_init = 'imu'"),
            std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\nresidual_gate_region = people\n")
                .find("residual_gate_region = 'people'"),
            std::string::npos);
  EXPECT_NE(
      errorOf("[FeatureTracking]\nmax_klt_residual_ratio = 0.5\n").find("max_klt_residual_ratio"),
      std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\nocclusion_edge_radius_px = -1\n")
                .find("occlusion_edge_radius_px"),
            std::string::npos);
  EXPECT_NE(errorOf("[FeatureTracking]\ndepth_edge_radius_px = -2\n").find("depth_edge_radius_px"),
            std::string::npos);
  EXPECT_NE(
      errorOf("[FeatureTracking]\nocclusion_edge_min_gap_m = 0\n").find("occlusion_edge_min_gap_m"),
      std::string::npos);
  const std::string e = errorOf("[FeatureTracking]\nfundamental_confidence = 1\n");
  EXPECT_NE(e.find("[FeatureTracking] in test.ini: fundamental_confidence"), std::string::npos)
      << e;
  EXPECT_NE(e.find("test.ini"), std::string::npos) << e;
}

TEST(FeatureTrackingStage, WritesStaticFeaturesWithIdsAndDepth) {
  FeatureTrackingStage stage;
  stage.configure(methodTrackingWith(""), "FeatureTracking");
  core::Frame first = texturedFrame(0, 0), second = texturedFrame(1, 6);
  stage.process(first);
  stage.process(second);
  ASSERT_EQ(first.features.size(), 150u);
  size_t continued = 0;
  for (const auto& f : second.features) {
    EXPECT_EQ(f.feature_class, core::FeatureClass::Static);
    EXPECT_EQ(f.object_id, -1);
    EXPECT_EQ(f.depth, 2.0f);
    if (f.track_length != 2) continue;
    ++continued;
    const auto it = std::find_if(first.features.begin(), first.features.end(),
                                 [&](const core::Feature& g) { return g.id == f.id; });
    ASSERT_NE(it, first.features.end());
    EXPECT_NEAR(f.pixel.x, it->pixel.x - 6, 0.1) << "the image moved 6 px left";
    EXPECT_NEAR(f.pixel.y, it->pixel.y, 0.1);
  }
  EXPECT_GT(continued, 130u);
  stage.finish();
  const auto stats = stage.statistics();
  const auto stat = [&](const std::string& name) {
    for (const auto& [k, v] : stats)
      if (k == name) return v;
    ADD_FAILURE() << "no statistic " << name;
    return -1.0;
  };
  EXPECT_EQ(stat("frames"), 2);
  EXPECT_EQ(stat("features_per_frame"), double(first.features.size() + second.features.size()) / 2);
  EXPECT_GT(stat("mean_track_length"), 1.0);
  EXPECT_LT(stat("mean_track_length"), 2.0);
  EXPECT_EQ(stat("gyro_frames"), 0) << "no IMU samples";
  // Each frame built a pyramid and extracted corners: both parts were timed (paper Table 8).
  EXPECT_GT(stat("tracking_ms_median"), 0.0);
  EXPECT_GT(stat("extraction_ms_median"), 0.0);
  core::Frame noColour = texturedFrame(2, 0);
  noColour.rgb.release();
  EXPECT_THROW(stage.process(noColour), std::invalid_argument);
}

namespace {

// The image moves 6 px left and its right third loses half its contrast, as when a patch
// slides onto another surface: KLT still converges there and most of those tracks pass the
// forward-backward check; only the residual (~2x the rest's, which carry 2 grey levels of
// noise) tells.
// personOnTheRight: 0 none, 1 a person's box 20 px right of the change with a sliver of
// mask, 2 the same box with all of it masked (the changed patches lie on the person).
double residualGateRun(const std::string& ini, int personOnTheRight, size_t& kept,
                       size_t& keptChanged) {
  FeatureTrackingStage stage;
  stage.configure(methodTrackingWith("fundamental_ransac = false\n" + ini), "FeatureTracking");
  core::Frame first = texturedFrame(0, 0), second = texturedFrame(1, 6);
  cv::Mat right = second.rgb(cv::Rect(440, 0, 200, 480));
  right.convertTo(right, -1, 0.5, 0.5 * 128);
  cv::RNG noise(5);
  for (auto* f : {&first, &second}) {
    cv::Mat n(f->rgb.size(), CV_16SC3);
    noise.fill(n, cv::RNG::NORMAL, 0, 2);
    cv::add(f->rgb, n, f->rgb, cv::noArray(), CV_8UC3);
  }
  if (personOnTheRight) {
    core::Detection person;
    person.box = cv::Rect2f(460, 0, 180, 480);
    person.category = "person";
    person.model = core::MotionModel::NonRigid;
    second.detections = {person};
    core::ObjectMask mask;
    mask.detection = 0;
    mask.roi = cv::Rect(460, 0, 180, 480);
    mask.mask = cv::Mat(480, 180, CV_8UC1, cv::Scalar(personOnTheRight == 2 ? 255 : 0));
    mask.mask.col(179).setTo(255);
    mask.valid = true;
    second.object_masks = {mask};
  }
  stage.process(first);
  stage.process(second);
  kept = keptChanged = 0;
  for (const auto& f : second.features) {
    if (f.track_length != 2) continue;
    ++kept;
    keptChanged += f.pixel.x > 450;
  }
  stage.finish();
  for (const auto& [k, v] : stage.statistics())
    if (k == "lost_residual_fraction") return v;
  return -1.0;
}

}  // namespace

TEST(FeatureTrackingStage, ResidualGateDropsPatchesWhoseAppearanceChanged) {
  const auto run = residualGateRun;
  size_t kept = 0, changed = 0;
  EXPECT_EQ(run("", 1, kept, changed), 0.0) << "the method's settings: the gate off";
  EXPECT_GT(changed, 20u) << "without the gate the changed patches are tracked";
  const size_t keptOff = kept, changedOff = changed;
  for (const int person : {0, 1}) {
    const std::string where = person ? "" : "residual_gate_region = everywhere\n";
    const double lost = run("max_klt_residual_ratio = 2\n" + where, person, kept, changed);
    EXPECT_LE(changed, changedOff / 4) << where;
    EXPECT_GT(lost, 0.1) << where;
    EXPECT_GE(kept - changed + 5, keptOff - changedOff) << where << ": the rest keep their tracks";
  }
  EXPECT_EQ(run("max_klt_residual_ratio = 2\n", 0, kept, changed), 0.0)
      << "near_nonrigid (the default) gates nothing without a non-rigid object";
  EXPECT_EQ(changed, changedOff);
  run("max_klt_residual_ratio = 2\n", 2, kept, changed);
  EXPECT_GE(changed + 3, changedOff) << "tracks on the person are the classification's to judge";
}
