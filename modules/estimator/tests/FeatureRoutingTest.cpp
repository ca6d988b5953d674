// Which features go where (FeatureRouting.h): landmarks, r_D, r_O / r_om, and the list of features
// whose static landmarks the window drops, for each dynamic_handling.
#include <dynslam/estimator/FeatureRouting.h>

#include <gtest/gtest.h>

using namespace dynslam;
using namespace dynslam::estimator;

namespace {

std::vector<core::Feature> oneOfEachClass() {
  std::vector<core::Feature> f(4);
  f[0].id = 1;  // background
  f[1].id = 2;  // a standing person: Static on an object
  f[1].object_id = 7;
  f[2].id = 3;
  f[2].feature_class = core::FeatureClass::NonRigid;
  f[2].object_id = 8;
  f[3].id = 4;
  f[3].feature_class = core::FeatureClass::Rigid;
  f[3].object_id = 9;
  for (auto& x : f) x.depth = 2.0f;
  return f;
}

std::vector<std::int64_t> ids(const std::vector<FeatureObservation>& o) {
  std::vector<std::int64_t> out;
  for (const auto& x : o) out.push_back(x.id);
  return out;
}

}  // namespace

TEST(FeatureRouting, NoneTakesEveryFeatureAsStaticAndCallsNoneMoving) {
  const auto r = routeFeatures(oneOfEachClass(), DynamicHandling::None, true, true);
  EXPECT_EQ(ids(r.landmarks), (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_TRUE(r.not_landmarks.empty());
  EXPECT_TRUE(r.nonrigid.empty());
  EXPECT_TRUE(r.rigid_objects.empty());
}

TEST(FeatureRouting, RemoveKeepsOnlyTheBackgroundLikeDynamicVins) {
  const auto r = routeFeatures(oneOfEachClass(), DynamicHandling::Remove, true, true);
  EXPECT_EQ(ids(r.landmarks), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(r.pixels.size(), 1u);
  EXPECT_EQ(r.not_landmarks, (std::vector<std::int64_t>{2, 3, 4}))
      << "the standing person is masked out with the walkers";
  EXPECT_TRUE(r.nonrigid.empty());
  EXPECT_TRUE(r.rigid_objects.empty());
}

TEST(FeatureRouting, FullKeepsTheStillOnesOnObjectsAndGivesTheMovingOnesTheirFactors) {
  const auto r = routeFeatures(oneOfEachClass(), DynamicHandling::Full, true, true);
  EXPECT_EQ(ids(r.landmarks), (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(ids(r.nonrigid), (std::vector<std::int64_t>{3}));
  ASSERT_EQ(r.rigid_objects.size(), 1u);
  EXPECT_EQ(r.rigid_objects[0].object_id, 9);
  EXPECT_EQ(ids(r.rigid_objects[0].features), (std::vector<std::int64_t>{4}));
  EXPECT_EQ(r.not_landmarks, (std::vector<std::int64_t>{3, 4}));

  const auto off = routeFeatures(oneOfEachClass(), DynamicHandling::Full, false, false);
  EXPECT_TRUE(off.nonrigid.empty());
  EXPECT_TRUE(off.rigid_objects.empty());
  EXPECT_EQ(off.not_landmarks, (std::vector<std::int64_t>{3, 4}))
      << "not landmarks whatever factors they get";
  EXPECT_EQ(ids(off.landmarks), (std::vector<std::int64_t>{1, 2}))
      << "without the object factors full keeps the standing person, unlike remove";
}

TEST(FeatureRouting, AReadingBesideADepthEdgeIsLeftOut) {
  auto features = oneOfEachClass();
  features[0].depth_at_edge = true;
  features[2].depth_at_edge = true;
  const auto r = routeFeatures(features, DynamicHandling::Full, true, true);
  ASSERT_EQ(r.landmarks.size(), 2u);
  EXPECT_EQ(r.landmarks[0].depth, 0.0) << "the pixel still counts, its reading does not";
  EXPECT_EQ(r.landmarks[1].depth, 2.0);
  ASSERT_EQ(r.nonrigid.size(), 1u);
  EXPECT_EQ(r.nonrigid[0].depth, 0.0);
}
