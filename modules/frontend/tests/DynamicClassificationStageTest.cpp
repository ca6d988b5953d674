// The DynamicClassification stage's ini contract: its section read, bad values and settings
// that act only through another refused, naming the keys.
#include <dynslam/core/Config.h>
#include <dynslam/frontend/DynamicClassificationStage.h>

#include <gtest/gtest.h>

namespace dynslam::frontend {
namespace {

TEST(DynamicClassificationStage, ReadsItsSectionAndRejectsBadValues) {
  DynamicClassificationStage stage;
  stage.configure(
      core::IniConfig::fromText("[DynamicClassification]\nspeed_threshold = 0.2\n"
                                "speed_statistic = mean_norm\nrigid_inlier_threshold = 0.05\n"),
      "DynamicClassification");
  EXPECT_EQ(stage.options().classifier.speed_threshold, 0.2);
  EXPECT_EQ(stage.options().classifier.speed_statistic, SpeedStatistic::MeanNorm);
  EXPECT_EQ(stage.options().classifier.rigid.ransac.inlier_threshold, 0.05);
  EXPECT_EQ(stage.options().classifier.rigid.ransac.iterations, 100);  // the method's default

  auto configure = [](const std::string& text) {
    DynamicClassificationStage s;
    s.configure(core::IniConfig::fromText("[DynamicClassification]\n" + text),
                "DynamicClassification");
  };
  auto messageOf = [&](const std::string& text) {
    try {
      configure(text);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(messageOf("speed_treshold = 0.1\n").find("speed_treshold"), std::string::npos);
  EXPECT_NE(messageOf("speed_window = 0\n").find("speed_window"), std::string::npos);
  EXPECT_NE(messageOf("speed_statistic = mean\n").find("speed_statistic"), std::string::npos);
  EXPECT_NE(messageOf("rigid_sample_size = 2\n").find("rigid_sample_size"), std::string::npos);
  EXPECT_NE(messageOf("far_object_min_depth = -1\n").find("far_object_min_depth"),
            std::string::npos);
  EXPECT_NE(messageOf("far_object_pixel_sigma = 0\n").find("far_object_pixel_sigma"),
            std::string::npos);
  EXPECT_NE(messageOf("rigid_rotation_prior_sigma = -0.01\n").find("rigid_rotation_prior_sigma"),
            std::string::npos);
  EXPECT_NE(messageOf("rigid_pixel_sigma = -0.3\n").find("rigid_pixel_sigma"), std::string::npos);
  EXPECT_NE(messageOf("rigid_ray_gate = 0\n").find("rigid_ray_gate"), std::string::npos);
  EXPECT_NE(messageOf("still_above_feet_fraction = 1\n").find("still_above_feet_fraction"),
            std::string::npos);
  EXPECT_NE(messageOf("start_moving_frames = 0\n").find("start_moving_frames"), std::string::npos);
}

TEST(DynamicClassificationStage, ASettingWithoutTheOneItActsThroughIsAnErrorNamingBoth) {
  const auto messageOf = [](const std::string& text) {
    try {
      DynamicClassificationStage s;
      s.configure(core::IniConfig::fromText("[DynamicClassification]\n" + text, "test.ini"),
                  "DynamicClassification");
    } catch (const core::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string stillOff = "still_feature_speed = 0\n";
  const std::string msg = messageOf(stillOff + "still_feature_in_still_box = true\n");
  EXPECT_NE(msg.find("still_feature_in_still_box"), std::string::npos) << msg;
  EXPECT_NE(msg.find("still_feature_speed > 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("test.ini"), std::string::npos) << msg;
  EXPECT_EQ(messageOf("still_feature_speed = 0.2\nstill_feature_in_still_box = true\n"), "");
  EXPECT_EQ(messageOf(stillOff), "")
      << "the defaults that act through still_feature_speed follow it when the ini turns it off";
  EXPECT_NE(messageOf(stillOff + "still_above_feet_fraction = 0.25\n")
                .find("still_above_feet_fraction"),
            std::string::npos);
  EXPECT_NE(messageOf("depth_sigma_z2 = 0\nrigid_noise_gates = true\nrigid_pixel_sigma = 0.3\n")
                .find("depth_sigma_z2 > 0"),
            std::string::npos);
  EXPECT_NE(messageOf("depth_window = 4\n").find("depth_window = 4"), std::string::npos)
      << "a rule beyond the key's range, named too";
}

}  // namespace
}  // namespace dynslam::frontend
