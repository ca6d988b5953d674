// Contract of the classification's object decisions (method.md section 3) on the synthetic
// scene (ClassifierScene.h): a walking person's features are dynamic and on a rigid set that
// moves like the person; a standing person's and a parked car's features are Static (members of
// the dynamic classes that do not move); a driving car's features are Rigid; the background is
// Static; features take the id of the track whose mask holds them. Also objects beyond the
// depth range, missed detections, the camera motion's background, start_moving_frames and what
// is forgotten.
#include "ClassifierScene.h"
#include "MethodSettings.h"

#include <dynslam/frontend/DynamicClassifier.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <map>
#include <random>
#include <set>

namespace dynslam::frontend {
namespace {

using namespace testing;

TEST(DynamicClassifier, ClassifiesMoversAndNonMovers) {
  const Scene scene;
  DynamicClassifier classifier(methodClassification());  // 0.1 m/s, window 10, method's RANSAC
  std::map<int, core::ObjectMotionState> last;
  core::Frame f;
  const int frames = 15;
  for (int k = 0; k < frames; ++k) {
    f = scene.frame(k);
    classifier.process(f);
    if (k == 0) continue;
    EXPECT_EQ(classifier.lastCameraMotion().source, CameraMotionSource::ImuRotationRegistration);
    const Eigen::Isometry3d truth = cameraPose(f.t).inverse() * cameraPose(f.t - kDt);
    EXPECT_LT((classifier.lastCameraMotion().motion.isometry().matrix() - truth.matrix()).norm(),
              1e-6)
        << "frame " << k;
  }
  for (const auto& s : f.object_motions) last[s.object_id] = s;
  ASSERT_EQ(last.size(), 4u);
  EXPECT_TRUE(last[1].dynamic);
  EXPECT_NEAR(last[1].speed, Eigen::Vector3d(0.8, 0, 0.3).norm(), 1e-6);
  EXPECT_FALSE(last[2].dynamic);
  EXPECT_LT(last[2].speed, 1e-6);
  EXPECT_FALSE(last[3].dynamic);
  EXPECT_TRUE(last[4].dynamic);
  EXPECT_NEAR(last[4].speed, 1.5, 1e-6);

  std::map<int, std::map<core::FeatureClass, int>> classes;
  for (const auto& feat : f.features) {
    const int expectedObject =
        feat.id < 1000 ? -1 : scene.objects[size_t(feat.id / 1000 - 1)].track_id;
    EXPECT_EQ(feat.object_id, expectedObject) << "feature " << feat.id;
    ++classes[feat.object_id][feat.feature_class];
  }
  using C = core::FeatureClass;
  EXPECT_EQ(classes[-1].size(), 1u);
  EXPECT_GT(classes[-1][C::Static], 50);
  EXPECT_EQ(classes[1][C::Rigid], 25);  // one rigid body: every feature is in the set
  EXPECT_EQ(classes[2][C::Static], 25);
  EXPECT_EQ(classes[3][C::Static], 25);
  EXPECT_EQ(classes[4][C::Rigid], 25);

  // Rigid sets of the two movers, with the camera-frame motion of their points.
  ASSERT_EQ(f.rigid_sets.size(), 2u);
  const Eigen::Isometry3d T_c1_w = cameraPose(f.t).inverse(), T_w_c0 = cameraPose(f.t - kDt);
  for (const auto& s : f.rigid_sets) {
    const auto& o = scene.objects[s.object_id == 1 ? 0 : 3];
    EXPECT_EQ(s.members.size(), 25u);
    const Eigen::Vector3d X0 = o.points[0] + o.velocity * (f.t - kDt);
    const Eigen::Vector3d p = T_w_c0.inverse() * X0, q = T_c1_w * (X0 + o.velocity * kDt);
    EXPECT_LT((s.R * p + s.t - q).norm(), 1e-6) << "object " << s.object_id;
  }
}

/// Appends to frame `f` an object beyond the depth range: its points (at time 0, world) move
/// with `velocity`; features without depth (ids idBase + i), a confirmed track `trackId` and the
/// mask the segmentation leaves without enough depth (invalid, the box as roi).
void addFarObject(core::Frame& f, int trackId, const std::vector<Eigen::Vector3d>& points,
                  const Eigen::Vector3d& velocity, std::int64_t idBase) {
  const Eigen::Isometry3d T_c_w = cameraPose(f.t).inverse();
  std::vector<cv::Point2f> px;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d P = T_c_w * (points[i] + velocity * f.t);
    core::Feature feat;
    feat.id = idBase + std::int64_t(i);
    feat.pixel = cv::Point2f(float(kCamera.fx * P.x() / P.z() + kCamera.cx),
                             float(kCamera.fy * P.y() / P.z() + kCamera.cy));
    feat.depth = 0;  // beyond the range
    f.features.push_back(feat);
    px.push_back(feat.pixel);
  }
  const cv::Rect box = cv::boundingRect(px);
  core::Track track;
  track.id = trackId;
  track.model = core::MotionModel::Rigid;
  track.state = core::TrackState::Confirmed;
  f.tracks.push_back(track);
  core::ObjectMask m;
  m.track = int(f.tracks.size() - 1);
  m.roi = cv::Rect(box.x - 3, box.y - 3, box.width + 6, box.height + 6);
  m.valid = false;
  f.object_masks.push_back(m);
}

/// Frames 0-14 of the scene with the two far cars of the test below added, through a classifier
/// with far_object_min_depth = `minDepth`; the last frame.
core::Frame classifyWithFarCars(double minDepth) {
  const Scene scene;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Vector3d> driving, parked;
  for (int i = 0; i < 30; ++i) {
    driving.emplace_back(-4 + 1.0 * u(rng), 0.5 + 0.4 * u(rng), 25 + 1.0 * u(rng));
    parked.emplace_back(-2 + 1.0 * u(rng), -1.5 + 0.4 * u(rng), 25 + 1.0 * u(rng));
  }
  DynamicClassifierParams params = methodClassification();
  params.far_object_min_depth = minDepth;
  DynamicClassifier classifier(params);
  core::Frame f;
  for (int k = 0; k < 15; ++k) {
    f = scene.frame(k);
    addFarObject(f, 5, driving, {5.0, 0, 0}, 50000);
    addFarObject(f, 6, parked, {0, 0, 0}, 60000);
    classifier.process(f);
  }
  return f;
}

/// The classes of the features with ids idBase..idBase + 999.
std::map<core::FeatureClass, int> classesOf(const core::Frame& f, std::int64_t idBase) {
  std::map<core::FeatureClass, int> n;
  for (const auto& feat : f.features)
    if (feat.id >= idBase && feat.id < idBase + 1000) ++n[feat.feature_class];
  return n;
}

// Two cars 25 m away, beyond the depth range: one drives across the view at 5 m/s, one is
// parked. By scene flow (the method) neither has a speed and their features stay Static; with
// far_object_min_depth = 10 the driving car's pixels leave the segment a static point beyond
// 10 m would keep to (FarPointMotion.h): it is dynamic and its features in the middle of its box
// NonRigid, while the parked car stays Static. The objects in range are classified as before.
TEST(DynamicClassifier, ObjectsBeyondTheDepthRangeAreJudgedFromTheirPixels) {
  const auto run = classifyWithFarCars;
  using C = core::FeatureClass;
  const core::Frame method = run(0.0);
  EXPECT_EQ(classesOf(method, 50000)[C::Static], 30) << "no depth, no scene flow: Static";
  for (const auto& s : method.object_motions) EXPECT_NE(s.object_id, 5);

  const core::Frame far = run(10.0);
  std::map<int, core::ObjectMotionState> motion;
  for (const auto& s : far.object_motions) motion[s.object_id] = s;
  ASSERT_TRUE(motion.count(5) && motion.count(6));
  EXPECT_TRUE(motion[5].dynamic);
  EXPECT_GT(motion[5].speed, 1.0) << "a lower bound of the 5 m/s";
  EXPECT_LT(motion[5].speed, 5.0);
  EXPECT_FALSE(motion[6].dynamic);
  EXPECT_LT(motion[6].speed, 0.01);
  // The features in the middle half of the box count (nearer its edge: mostly background and
  // silhouette); no depth, so no rigid set: NonRigid.
  cv::Rect box;
  for (const auto& m : far.object_masks)
    if (!m.valid && far.tracks[size_t(m.track)].id == 5) box = m.roi;
  const cv::Rect middle(box.x + box.width / 4, box.y + box.height / 4, box.width / 2,
                        box.height / 2);
  int inMiddle = 0;
  for (const auto& feat : far.features)
    inMiddle += feat.id >= 50000 && feat.id < 51000 &&
                middle.contains({cvRound(feat.pixel.x), cvRound(feat.pixel.y)});
  ASSERT_GE(inMiddle, 3);
  EXPECT_EQ(classesOf(far, 50000)[C::NonRigid], inMiddle);
  EXPECT_EQ(classesOf(far, 50000)[C::Static], 30 - inMiddle);
  EXPECT_EQ(classesOf(far, 60000)[C::Static], 30);
  for (const auto& feat : far.features) {
    if (feat.id >= 50000 && feat.id < 51000 && feat.feature_class == C::NonRigid) {
      EXPECT_EQ(feat.object_id, 5) << "feature " << feat.id;
    }
  }
  EXPECT_TRUE(motion[1].dynamic);
  EXPECT_FALSE(motion[2].dynamic);
  EXPECT_TRUE(motion[4].dynamic);
}

TEST(DynamicClassifier, AMissedDetectionKeepsTheObjectsFeaturesWhileItsTrackCoasts) {
  const Scene scene;
  DynamicClassifier classifier(methodClassification());
  core::Frame f;
  for (int k = 0; k < 12; ++k) {
    f = scene.frame(k);
    if (k == 11) f.object_masks.erase(f.object_masks.begin());  // the walker's detection missed
    classifier.process(f);
  }
  int walker = 0;
  for (const auto& feat : f.features)
    if (feat.id >= 1000 && feat.id < 2000) {
      ++walker;
      EXPECT_EQ(feat.object_id, 1) << "feature " << feat.id;
      EXPECT_NE(feat.feature_class, core::FeatureClass::Static) << "feature " << feat.id;
    }
  EXPECT_EQ(walker, 25);
}

// The walker's mask misses the right half of its box, as masks miss a tenth of a walker's
// pixels: those features are outside every mask but inside the walker's box. Registered on
// them too, the camera's translation takes some of the walker's motion; registered on the
// features outside every box (the default) it stays exact.
TEST(DynamicClassifier, TheCameraMotionIgnoresFeaturesInsideBoxesButOutsideMasks) {
  auto worstError = [](bool outsideBoxes) {
    const Scene scene;
    DynamicClassifierParams params = methodClassification();
    params.background_outside_boxes = outsideBoxes;
    DynamicClassifier classifier(params);
    double worst = 0;
    for (int k = 0; k < 15; ++k) {
      core::Frame f = scene.frame(k);
      cv::Mat& walker = f.object_masks[0].mask;
      walker.colRange(walker.cols / 2, walker.cols).setTo(0);
      classifier.process(f);
      if (k == 0) continue;
      const Eigen::Isometry3d truth = cameraPose(f.t).inverse() * cameraPose(f.t - kDt);
      worst =
          std::max(worst, (classifier.lastCameraMotion().motion.t - truth.translation()).norm());
    }
    return worst;
  };
  EXPECT_LT(worstError(true), 1e-6);
  EXPECT_GT(worstError(false), 1e-3) << "the walker's features outvote the far background";
}

TEST(DynamicClassifier, TheMethodsFrameToFrameSettingsAgreeOnCleanData) {
  const Scene scene;
  DynamicClassifierParams params = methodClassification();
  params.speed_window = 1;
  params.speed_statistic = SpeedStatistic::MeanNorm;
  DynamicClassifier classifier(params);
  core::Frame f;
  for (int k = 0; k < 3; ++k) {
    f = scene.frame(k);
    classifier.process(f);
  }
  std::map<int, bool> dynamic;
  for (const auto& s : f.object_motions) dynamic[s.object_id] = s.dynamic;
  EXPECT_TRUE(dynamic[1]);
  EXPECT_FALSE(dynamic[2]);
  EXPECT_FALSE(dynamic[3]);
  EXPECT_TRUE(dynamic[4]);
}

// On frame 12 the segmentation gives the walker's surface to the standing person's track and the
// standing person's to the walker's (their track ids swap for that frame): by the method the
// standing person moves on that frame. With start_moving_frames = 2 a still object needs two
// measured frames in a row over the threshold, so the one-frame swap leaves it still, while the
// walker, already moving, is decided at once as before. A swap held for two frames turns it.
TEST(DynamicClassifier, AStillObjectStartsMovingOnlyAfterStartMovingFramesInARow) {
  auto standingDynamic = [](int startMovingFrames, int swapFrames) {
    DynamicClassifierParams params = methodClassification();
    params.start_moving_frames = startMovingFrames;
    const Scene scene;
    DynamicClassifier classifier(params);
    std::vector<bool> dynamic;
    for (int k = 0; k < 16; ++k) {
      core::Frame f = scene.frame(k);
      if (k >= 12 && k < 12 + swapFrames) std::swap(f.tracks[0].id, f.tracks[1].id);
      classifier.process(f);
      for (const auto& s : f.object_motions)
        if (s.object_id == 2) dynamic.push_back(s.dynamic);
    }
    return dynamic;
  };
  const auto method = standingDynamic(1, 1);
  ASSERT_EQ(method.size(), 16u);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(method[k], k == 12) << "method, frame " << k;
  const auto debounced = standingDynamic(2, 1);
  for (int k = 0; k < 16; ++k) EXPECT_FALSE(debounced[k]) << "start_moving_frames 2, frame " << k;
  const auto held = standingDynamic(2, 2);
  EXPECT_FALSE(held[12]);
  EXPECT_TRUE(held[13]) << "the second frame in a row turns it";
}

// Object ids are never reused and a street sees thousands of tracks a minute (bench-classification,
// outdoor_street_high: 3388 tracks started in 20 s): what the classifier keeps per object is
// forgotten once an object has not been decided for kObjectMemoryS, so a long run's memory and
// per-frame work stay bounded. Here every frame renumbers the four objects, at 10 frames a second
// for 60 s.
TEST(DynamicClassifier, ForgetsObjectsNotSeenForLong) {
  const Scene scene;
  DynamicClassifier classifier(methodClassification());
  std::map<int, double> decidedAt;  // object id -> when it was decided
  double t = 0;
  for (int k = 0; k < 600; ++k) {
    core::Frame f = scene.frame(k);
    f.t = t = 0.1 * k;
    for (size_t j = 0; j < f.tracks.size(); ++j) f.tracks[j].id = 10 + 4 * k + int(j);
    classifier.process(f);
    for (const auto& s : f.object_motions) decidedAt[s.object_id] = f.t;
  }
  size_t recent = 0, possiblyRecent = 0;  // decided within the memory (give or take 0.05 s)
  for (const auto& [id, at] : decidedAt) {
    recent += at > t - DynamicClassifier::kObjectMemoryS + 0.05;
    possiblyRecent += at > t - DynamicClassifier::kObjectMemoryS - 0.05;
  }
  EXPECT_GE(classifier.rememberedObjects(), recent);
  EXPECT_LE(classifier.rememberedObjects(), possiblyRecent);
  EXPECT_GT(decidedAt.size(), 2 * possiblyRecent) << "the objects of the first 30 s are forgotten";
}

}  // namespace
}  // namespace dynslam::frontend
