// The rules on single features that move in a still object's mask, or measure a depth jump
// (moving_feature_speed with the noise margin, max_nonrigid_flow_speed), on the synthetic scene
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

// The converse: the standing person's mask grows over the walker (a walker less than e behind a
// standing person, whose own detection is missed). By the object's class the walker's features
// there turn Static; with moving_feature_speed they are NonRigid, as they move, while the
// standing person's own features stay Static.
TEST(DynamicClassifier, MovingFeaturesInAStillObjectsMaskAreNonRigid) {
  auto run = [](double movingSpeed) {
    DynamicClassifierParams params = methodClassification();
    params.moving_feature_speed = movingSpeed;
    const core::Frame f = classifyWithEditedMasks(params, [](std::vector<core::ObjectMask>& m) {
      const cv::Rect roi = m[0].roi | m[1].roi;
      m[1].roi = roi;
      m[1].mask = cv::Mat(roi.size(), CV_8UC1, cv::Scalar(255));
      m.erase(m.begin());
    });
    int walkerInStill = 0, walkerNonRigid = 0, standingStatic = 0, standing = 0;
    for (const auto& feat : f.features) {
      if (feat.id >= 1000 && feat.id < 2000 && feat.object_id == 2) {
        ++walkerInStill;
        walkerNonRigid += feat.feature_class == core::FeatureClass::NonRigid;
      }
      if (feat.id >= 2000 && feat.id < 3000) {
        ++standing;
        standingStatic += feat.feature_class == core::FeatureClass::Static;
      }
    }
    EXPECT_EQ(walkerInStill, 25) << "the standing person's mask holds the walker";
    EXPECT_EQ(standingStatic, standing) << "the standing person's own features stay Static";
    return walkerNonRigid;
  };
  EXPECT_EQ(run(0.0), 0) << "by the object's class: Static";
  EXPECT_EQ(run(0.5), 25) << "the walker's features move at 0.85 m/s: NonRigid";
}

// ... but by more than the flow's depth noise (speed_noise_sigmas): five of the parked car's
// corners are new every other frame (one-frame flows) and read 1.2 m/s of depth jitter (+-2 cm
// per frame at 4.5 m), within two sigmas of the sensor model's noise (about 0.3 m/s).
TEST(DynamicClassifier, AStillObjectsNoisyFlowIsNotMotion) {
  auto run = [](double sigmas) {
    DynamicClassifierParams params = methodClassification();
    params.moving_feature_speed = 0.8;  // as shipped
    params.speed_noise_sigmas = sigmas;
    const Scene scene;
    DynamicClassifier classifier(params);
    core::Frame f;
    for (int k = 0; k < 16; ++k) {  // the last frame's corners have a one-frame flow
      f = scene.frame(k);
      for (auto& feat : f.features)
        if (feat.id >= 3000 && feat.id < 3005) {
          feat.depth += (k % 2 ? 0.02f : -0.02f);
          feat.id += 100000 * (k / 2);  // a new corner every other frame
        }
      classifier.process(f);
    }
    int noisy = 0, noisyNonRigid = 0, carStatic = 0;
    for (const auto& feat : f.features) {
      if (feat.object_id != 3) continue;
      carStatic += feat.feature_class == core::FeatureClass::Static;
      if (feat.id >= 100000) {
        ++noisy;
        noisyNonRigid += feat.feature_class == core::FeatureClass::NonRigid;
      }
    }
    EXPECT_EQ(noisy, 5);
    EXPECT_GE(carStatic, 20) << "the car is judged still";
    return noisyNonRigid;
  };
  EXPECT_EQ(run(0.0), 5) << "without the margin the jitter passes for motion";
  EXPECT_EQ(run(2.0), 0) << "1.2 m/s of depth noise on a one-frame flow is not motion";
}

// Most of a standing person's features read the wall 2.5 m behind from frame 12 on (tracks that
// slid off its silhouette, depth windows that flipped surfaces): their flow, metres per second,
// outvotes the still ones in the component-wise median and the person is judged moving. With
// max_nonrigid_flow_speed those flows measure nothing and the person stays still.
TEST(DynamicClassifier, FlowsFasterThanAPersonMovesAreDepthJumpsNotMotion) {
  auto run = [](double maxSpeed) {
    DynamicClassifierParams params = methodClassification();
    params.max_nonrigid_flow_speed = maxSpeed;
    const Scene scene;
    DynamicClassifier classifier(params);
    core::Frame f;
    for (int k = 0; k < 15; ++k) {
      f = scene.frame(k);
      if (k >= 12)
        for (auto& feat : f.features)
          if (feat.id >= 2000 && feat.id < 2015) feat.depth += 2.5f;
      classifier.process(f);
    }
    int standing = 0, standingStatic = 0, walkerDynamic = 0;
    for (const auto& feat : f.features) {
      if (feat.id >= 2000 && feat.id < 3000) {
        ++standing;
        standingStatic += feat.feature_class == core::FeatureClass::Static;
      }
      if (feat.id >= 1000 && feat.id < 2000)
        walkerDynamic += feat.feature_class != core::FeatureClass::Static;
    }
    EXPECT_EQ(walkerDynamic, 25) << "the walker (0.85 m/s) is measured as before";
    return std::make_pair(standingStatic, standing);
  };
  EXPECT_EQ(run(0.0).first, 0) << "15 of 25 flows read the wall's jump: judged moving";
  const auto gated = run(2.5);
  EXPECT_EQ(gated.first, gated.second) << "the jumps measure nothing: still, every feature Static";
}

}  // namespace
}  // namespace dynslam::frontend
