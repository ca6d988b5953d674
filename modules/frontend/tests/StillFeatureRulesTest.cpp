// The rules on single features that keep still features Static where a moving object's mask
// took them (still_feature_speed, still_feature_in_still_box, unmeasured_feature_by_depth,
// still_carried_outside_box, still_above_feet_fraction), on the synthetic scene
// (ClassifierScene.h).
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

/// The walker's mask (m[0]) grown over the left half of the standing person's box (m[1]): the
/// walker's pixels and those of that half, not the wall between them, as a mask holds every pixel
/// of its box within its depth range.
cv::Rect growWalkerMaskOverStandingHalf(std::vector<core::ObjectMask>& m) {
  cv::Rect half = m[1].roi;
  half.width /= 2;
  const cv::Rect roi = m[0].roi | half;
  cv::Mat mask(roi.size(), CV_8UC1, cv::Scalar(0));
  mask(m[0].roi - roi.tl()).setTo(255);
  mask(half - roi.tl()).setTo(255);
  m[0].roi = roi;
  m[0].mask = mask;
  return half;
}

// The walker's mask grows over the left half of the standing person (a mask holds every pixel of
// its box within its depth range; here the standing person's own detection is missed too): by
// the object's class the standing person's features there turn dynamic; with
// still_feature_speed they stay Static, as they did not move, while the walker's own features
// stay dynamic.
TEST(DynamicClassifier, StillStaticFeaturesStayStaticUnderAMovingObjectsMask) {
  auto run = [](double stillSpeed) {
    DynamicClassifierParams params = methodClassification();
    params.still_feature_speed = stillSpeed;
    const core::Frame f = classifyWithEditedMasks(params, [](std::vector<core::ObjectMask>& m) {
      growWalkerMaskOverStandingHalf(m);
      m.erase(m.begin() + 1);
    });
    int onWalker = 0, staticOnWalker = 0, walkerDynamic = 0;
    for (const auto& feat : f.features) {
      if (feat.id >= 2000 && feat.id < 3000 && feat.object_id == 1) {
        ++onWalker;
        staticOnWalker += feat.feature_class == core::FeatureClass::Static;
      }
      if (feat.id >= 1000 && feat.id < 2000)
        walkerDynamic += feat.feature_class != core::FeatureClass::Static;
    }
    EXPECT_GE(onWalker, 5) << "the walker's mask holds some of them";
    EXPECT_EQ(walkerDynamic, 25);
    return std::make_pair(staticOnWalker, onWalker);
  };
  const auto method = run(0.0);
  EXPECT_EQ(method.first, 0) << "by the object's class: dynamic";
  const auto still = run(0.2);
  EXPECT_EQ(still.first, still.second) << "still: Static";
}

// From frame 12 on the walker's mask holds the standing person's left half (the walker passing
// within e of it) and the standing person's features are new tracks (ids + 3000: lost and found
// again), its own mask still there: those features never were Static, so still_feature_speed
// alone leaves them dynamic; still_feature_in_still_box makes them Static, as they are still
// and inside the box of an object judged not to move.
TEST(DynamicClassifier, StillFeaturesInAStillObjectsBoxAreStaticThoughNeverStaticBefore) {
  auto run = [](bool inStillBox) {
    DynamicClassifierParams params = methodClassification();
    params.still_feature_speed = 0.2;
    params.still_feature_in_still_box = inStillBox;
    const Scene scene;
    DynamicClassifier classifier(params);
    core::Frame f;
    std::set<std::int64_t> heldFromTheStart;
    for (int k = 0; k < 15; ++k) {
      f = scene.frame(k);
      if (k >= 12) {
        growWalkerMaskOverStandingHalf(f.object_masks);
        for (auto& feat : f.features)
          if (feat.id >= 2000 && feat.id < 3000) feat.id += 3000;
      }
      classifier.process(f);
      if (k == 12)  // held by the walker's mask since they appeared
        for (const auto& feat : f.features)
          if (feat.id >= 5000 && feat.id < 6000 && feat.object_id == 1)
            heldFromTheStart.insert(feat.id);
    }
    int onWalker = 0, staticOnWalker = 0, walkerDynamic = 0, standingOwnStatic = 0;
    for (const auto& feat : f.features) {
      if (heldFromTheStart.count(feat.id) && feat.object_id == 1) {
        ++onWalker;
        staticOnWalker += feat.feature_class == core::FeatureClass::Static;
      }
      if (feat.id >= 5000 && feat.id < 6000 && feat.object_id == 2)
        standingOwnStatic += feat.feature_class == core::FeatureClass::Static;
      if (feat.id >= 1000 && feat.id < 2000)
        walkerDynamic += feat.feature_class != core::FeatureClass::Static;
    }
    EXPECT_GE(onWalker, 5) << "the walker's mask holds some of them";
    EXPECT_GE(standingOwnStatic, 5) << "the rest are the standing person's, judged still";
    EXPECT_EQ(walkerDynamic, 25) << "the walker's own features stay dynamic";
    return std::make_pair(staticOnWalker, onWalker);
  };
  EXPECT_EQ(run(false).first, 0) << "never Static before: dynamic";
  const auto inBox = run(true);
  EXPECT_EQ(inBox.first, inBox.second) << "still, in a still object's box: Static";
}

// The frame the standing person's features reappear as new tracks (ids + 3000) inside the
// walker's mask (its left half, as above) they have no scene flow yet, so the still rules cannot
// speak for them and they took the walker's class. With unmeasured_feature_by_depth their depth,
// nearer the standing person's d_t than the walker's, makes them Static; a new corner there at
// the walker's own depth stays the walker's.
TEST(DynamicClassifier, NewFeaturesInAStillObjectsBoxGoByDepth) {
  auto run = [](bool byDepth) {
    DynamicClassifierParams params = methodClassification();
    params.still_feature_speed = 0.2;
    params.still_feature_in_still_box = true;
    params.unmeasured_feature_by_depth = byDepth;
    const Scene scene;
    DynamicClassifier classifier(params);
    core::Frame f;
    for (int k = 0; k <= 12; ++k) {
      f = scene.frame(k);
      if (k == 12) {
        auto& m = f.object_masks;
        const cv::Rect half = growWalkerMaskOverStandingHalf(m);
        for (auto& feat : f.features)
          if (feat.id >= 2000 && feat.id < 3000) feat.id += 3000;
        core::Feature walkerCorner;  // a new corner on the walker, in the standing one's box
        walkerCorner.id = 9000;
        walkerCorner.pixel = cv::Point2f(half.x + 2.f, half.y + half.height / 2.f);
        walkerCorner.depth = float(m[0].d_t);
        f.features.push_back(walkerCorner);
      }
      classifier.process(f);
    }
    int onWalker = 0, staticOnWalker = 0, walkerDynamic = 0, cornerStatic = -1;
    for (const auto& feat : f.features) {
      if (feat.id >= 5000 && feat.id < 6000 && feat.object_id == 1) {
        ++onWalker;
        staticOnWalker += feat.feature_class == core::FeatureClass::Static;
      }
      if (feat.id >= 1000 && feat.id < 2000)
        walkerDynamic += feat.feature_class != core::FeatureClass::Static;
      if (feat.id == 9000) {
        EXPECT_EQ(feat.object_id, 1) << "the walker's mask holds the corner";
        cornerStatic = feat.feature_class == core::FeatureClass::Static;
      }
    }
    EXPECT_GE(onWalker, 5) << "the walker's mask holds some of them";
    EXPECT_EQ(walkerDynamic, 25) << "the walker's own features stay dynamic";
    EXPECT_EQ(cornerStatic, 0) << "at the walker's depth: the walker's class";
    return std::make_pair(staticOnWalker, onWalker);
  };
  EXPECT_EQ(run(false).first, 0) << "no flow yet: the walker's class";
  const auto byDepth = run(true);
  EXPECT_EQ(byDepth.first, byDepth.second) << "nearer the standing person's depth: Static";
}

// A walker's mask that once spilled over background (here: its box grown by 60 px for one
// frame, as a mask takes a wall within e of the walker) gives the new corners there the
// walker's membership, and with no mask holding them after it carries over frame to frame.
// Their own scene flow says they are still and they lie outside the walker's track box: with
// still_carried_outside_box they are Static and off the walker. The walker's own features,
// carried inside its box while its detection is missed (no mask on the last three frames),
// stay dynamic.
TEST(DynamicClassifier, StillFeaturesCarriedOutsideTheTracksBoxLeaveTheObject) {
  auto run = [](bool leave) {
    DynamicClassifierParams params = methodClassification();
    params.still_feature_speed = 0.2;
    params.still_carried_outside_box = leave;
    const Scene scene;
    DynamicClassifier classifier(params);
    core::Frame f;
    std::set<std::int64_t> grabbed;
    for (int k = 0; k < 15; ++k) {
      f = scene.frame(k);
      for (size_t j = 0; j < f.tracks.size(); ++j)
        f.tracks[j].box = cv::Rect2f(f.object_masks[j].roi);
      auto& walker = f.object_masks[0];
      if (k >= 4)  // new corners from frame 4 on: no flow yet when the spilled mask takes them
        for (auto& feat : f.features)
          if (feat.id < 1000) feat.id += 500;
      if (k == 4) {
        walker.roi =
            cv::Rect(walker.roi.x, walker.roi.y, walker.roi.width + 60, walker.roi.height) &
            cv::Rect(0, 0, 640, 480);
        walker.mask = cv::Mat(walker.roi.size(), CV_8UC1, cv::Scalar(255));
      }
      if (k >= 12) walker.valid = false;  // the detector misses the walker: its track coasts
      classifier.process(f);
      if (k == 4)
        for (const auto& feat : f.features)
          if (feat.id < 1000 && feat.object_id == 1) grabbed.insert(feat.id);
    }
    int grabbedSeen = 0, grabbedStatic = 0, grabbedOnWalker = 0, walker = 0, walkerDynamic = 0;
    for (const auto& feat : f.features) {
      if (feat.object_id > 1) continue;  // in another object's mask now: not carried
      if (grabbed.count(feat.id)) {
        ++grabbedSeen;
        grabbedStatic += feat.feature_class == core::FeatureClass::Static;
        grabbedOnWalker += feat.object_id == 1;
      }
      if (feat.id >= 1000 && feat.id < 2000) {
        ++walker;
        walkerDynamic += feat.feature_class != core::FeatureClass::Static;
      }
    }
    EXPECT_GE(grabbedSeen, 3) << "the spilled mask took some background features";
    EXPECT_GE(walker, 20);
    EXPECT_EQ(walkerDynamic, walker) << "carried inside its box, the walker's own stay dynamic";
    return std::make_tuple(grabbedSeen, grabbedStatic, grabbedOnWalker);
  };
  const auto [seenOff, staticOff, onWalkerOff] = run(false);
  EXPECT_EQ(staticOff, 0) << "carried over, they took the walker's class";
  EXPECT_EQ(onWalkerOff, seenOff);
  const auto [seenOn, staticOn, onWalkerOn] = run(true);
  EXPECT_EQ(staticOn, seenOn) << "still and outside the walker's box: Static";
  EXPECT_EQ(onWalkerOn, 0) << "and no longer the walker's";
}

// A walker's mask holds every box pixel within e of its depth: a wall just behind it, above its
// feet, becomes the walker's. Static world points seen inside the walker's box from frame 10 on:
// "wall" ones in the upper part of the box, "foot" ones in its bottom tenth (a planted foot is
// still too). With still_above_feet_fraction = 0.25 the wall's are Static once their flow says
// they are still; the feet's, and the walker's own moving features, stay dynamic.
TEST(DynamicClassifier, StillFeaturesAboveAWalkersFeetAreStatic) {
  const Scene scene;
  const Eigen::Isometry3d T_w_c12 = cameraPose(12 * kDt);
  const cv::Rect box12 = scene.frame(12).object_masks[0].roi;
  std::vector<std::pair<std::int64_t, Eigen::Vector3d>> wall, feet;  // id, world point
  for (int i = 0; i < 6; ++i) {
    const double u = box12.x + box12.width * (0.4 + 0.04 * i);
    const auto at = [&](double v) {
      return T_w_c12 * Eigen::Vector3d((u - kCamera.cx) / kCamera.fx * 3.1,
                                       (v - kCamera.cy) / kCamera.fy * 3.1, 3.1);
    };
    wall.emplace_back(7000 + i, at(box12.y + box12.height * (0.15 + 0.08 * i)));
    feet.emplace_back(8000 + i, at(box12.y + box12.height * 0.95));
  }
  auto run = [&](double fraction) {
    DynamicClassifierParams params = methodClassification();
    params.still_feature_speed = 0.2;
    params.still_above_feet_fraction = fraction;
    DynamicClassifier classifier(params);
    core::Frame f;
    for (int k = 0; k < 15; ++k) {
      f = scene.frame(k);
      const Eigen::Isometry3d T_c_w = cameraPose(f.t).inverse();
      if (k >= 10)
        for (const auto& group : {wall, feet})
          for (const auto& [id, X] : group) {
            const Eigen::Vector3d P = T_c_w * X;
            core::Feature feat;
            feat.id = id;
            feat.pixel = cv::Point2f(float(kCamera.fx * P.x() / P.z() + kCamera.cx),
                                     float(kCamera.fy * P.y() / P.z() + kCamera.cy));
            feat.depth = float(P.z());
            f.features.push_back(feat);
          }
      classifier.process(f);
    }
    std::map<std::string, std::pair<int, int>> seen;  // group -> features on the walker, Static
    for (const auto& feat : f.features) {
      const std::string group = feat.id >= 8000                     ? "feet"
                                : feat.id >= 7000                   ? "wall"
                                : feat.id >= 1000 && feat.id < 2000 ? "walker"
                                                                    : "";
      if (group.empty() || feat.object_id != 1) continue;
      ++seen[group].first;
      seen[group].second += feat.feature_class == core::FeatureClass::Static;
    }
    EXPECT_GE(seen["wall"].first, 4) << "the walker's mask holds the wall behind it";
    EXPECT_GE(seen["feet"].first, 4);
    EXPECT_EQ(seen["feet"].second, 0) << "still, but where its feet are: the walker's";
    EXPECT_EQ(seen["walker"].second, 0) << "the walker's own features move";
    return seen["wall"];
  };
  EXPECT_EQ(run(0).second, 0) << "off: the wall in the walker's mask takes its class";
  const auto on = run(0.25);
  EXPECT_EQ(on.second, on.first) << "still above its feet: Static";
}

}  // namespace
}  // namespace dynslam::frontend
