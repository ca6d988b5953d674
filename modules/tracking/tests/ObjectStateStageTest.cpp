#include "CylinderFrame.h"

#include <dynslam/core/Config.h>
#include <dynslam/tracking/ObjectStateStage.h>

#include <gtest/gtest.h>

using namespace dynslam;
using namespace dynslam::tracking;
using test_support::Cylinder;
using test_support::cylinderFrame;

namespace {

constexpr double kDt = 1.0 / 30;

/// A body walking across the view at `speed` m/s, 3 m away, seen in frame k.
core::Frame walkerFrame(int k, double speed, int track_id) {
  return cylinderFrame(k * kDt, Cylinder{-0.8 + speed * k * kDt, 3.0}, track_id);
}

/// Frames first .. last - 1 of that walker through `stage` (`hidden`: no mask, its track
/// coasting); returns the last frame.
core::Frame walk(ObjectStateStage& stage, int first, int last, double speed, int track_id,
                 bool hidden = false) {
  core::Frame f;
  for (int k = first; k < last; ++k) {
    f = walkerFrame(k, speed, track_id);
    if (hidden) f.object_masks.clear();
    stage.process(f);
  }
  return f;
}

double statistic(const ObjectStateStage& stage, const std::string& name) {
  for (const auto& [key, value] : stage.statistics())
    if (key == name) return value;
  ADD_FAILURE() << "no statistic " << name;
  return 0;
}

const core::ObjectState& only(const core::Frame& f) {
  EXPECT_TRUE(f.object_states);
  EXPECT_EQ(f.object_states->size(), 1u);
  return f.object_states->front();
}

TEST(ObjectStateStage, AWalkerGetsItsCentreAndVelocity) {
  ObjectStateStage stage;
  core::Frame f = walk(stage, 0, 45, 1.0, 7);
  const auto& s = only(f);
  EXPECT_EQ(s.track_id, 7);
  EXPECT_EQ(s.category, "person");
  EXPECT_TRUE(s.measured);
  EXPECT_TRUE(s.moving);
  EXPECT_NEAR(s.velocity.x(), 1.0, 0.1) << s.velocity.transpose();
  EXPECT_NEAR(s.velocity.z(), 0.0, 0.1);
  const double x = -0.8 + 44 * kDt;
  // The default thickness (half the width) puts the centre about 7 cm short of the axis of a
  // round body; a walker's torso is flatter.
  EXPECT_NEAR(s.centre.x(), x, 0.1);
  EXPECT_NEAR(s.centre.z(), 3.0, 0.1);
  EXPECT_NEAR(s.up.y(), -1.0, 1e-9);
  EXPECT_LT(s.covariance(3, 3), 0.3 * 0.3);
}

TEST(ObjectStateStage, AnOccludedWalkerIsPredictedThenDropped) {
  ObjectStateOptions options;
  options.max_coast_s = 0.5;
  ObjectStateStage stage(options);
  core::Frame f = walk(stage, 0, 30, 1.0, 7);
  const int id = only(f).id;
  const double x = only(f).centre.x();
  f = walk(stage, 30, 40, 1.0, 7, true);  // hidden: the track coasts
  EXPECT_EQ(only(f).id, id);
  EXPECT_FALSE(only(f).measured);
  EXPECT_NEAR(only(f).centre.x() - x, 10 * kDt, 0.05);  // carried on at its velocity
  f = walk(stage, 40, 50, 1.0, 7, true);
  ASSERT_TRUE(f.object_states);
  EXPECT_TRUE(f.object_states->empty());
}

TEST(ObjectStateStage, ATrackMadeAgainWhereAStateCoastsContinuesItsId) {
  ObjectStateStage stage;
  core::Frame f = walk(stage, 0, 30, 1.0, 7);
  const int id = only(f).id;
  for (int k = 30; k < 35; ++k) {  // the tracker lost it, then made track 9 on it
    f = walkerFrame(k, 1.0, k < 33 ? 7 : 9);
    if (k < 33) f.object_masks.clear();
    stage.process(f);
  }
  EXPECT_EQ(only(f).id, id);
  EXPECT_EQ(only(f).track_id, 9);
  EXPECT_TRUE(only(f).measured);
  EXPECT_EQ(statistic(stage, "reassociated"), 1.0);
}

TEST(ObjectStateStage, ATrackThatJumpsToAnotherBodyStartsANewState) {
  ObjectStateStage stage;
  core::Frame f = walk(stage, 0, 30, 0.5, 7);
  const int id = only(f).id;
  // Track 7 now on a body 1.8 m away: the first gate_frames - 1 frames are skipped as outliers.
  for (int k = 30; k < 32; ++k) {
    f = cylinderFrame(k * kDt, Cylinder{1.5, 3.0}, 7);
    stage.process(f);
    EXPECT_EQ(only(f).id, id);
    EXPECT_FALSE(only(f).measured);
    EXPECT_EQ(only(f).track_id, 7);
  }
  f = cylinderFrame(32 * kDt, Cylinder{1.5, 3.0}, 7);
  stage.process(f);
  ASSERT_EQ(f.object_states->size(), 2u);
  const auto& old = f.object_states->at(0);
  const auto& made = f.object_states->at(1);
  EXPECT_EQ(old.id, id);
  EXPECT_FALSE(old.measured);
  EXPECT_EQ(old.track_id, -1);
  EXPECT_NE(made.id, id);
  EXPECT_EQ(made.track_id, 7);
  EXPECT_TRUE(made.measured);
}

TEST(ObjectStateStage, OneMeasurementOutsideTheGateIsSkipped) {
  ObjectStateStage stage;
  core::Frame f = walk(stage, 0, 30, 0.5, 7);
  const int id = only(f).id;
  const double x = only(f).centre.x();
  f = cylinderFrame(30 * kDt, Cylinder{1.5, 3.0}, 7);  // another body's pixels, one frame
  stage.process(f);
  EXPECT_NEAR(only(f).centre.x() - x, 0.5 * kDt, 0.02);
  f = walk(stage, 31, 35, 0.5, 7);
  EXPECT_EQ(only(f).id, id);
  EXPECT_TRUE(only(f).measured);
  EXPECT_EQ(statistic(stage, "gated"), 0.0);
}

TEST(ObjectStateStage, AFrameWithoutACameraPoseOnlyPredicts) {
  ObjectStateStage stage;
  core::Frame f = walk(stage, 0, 10, 1.0, 7);
  f = walkerFrame(10, 1.0, 7);
  f.T_world_camera.reset();
  stage.process(f);
  EXPECT_FALSE(only(f).measured);
}

TEST(ObjectStateStage, UnknownKeysAndBadValuesAreErrorsNamingTheKey) {
  ObjectStateStage stage;
  for (const char* ini :
       {"[ObjectStates]\nmax_coast = 1\n", "[ObjectStates]\nmax_coast_s = -1\n"}) {
    try {
      stage.configure(core::IniConfig::fromText(ini, "test.ini"), "ObjectStates");
      FAIL() << "accepted: " << ini;
    } catch (const core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("max_coast"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("test.ini"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
