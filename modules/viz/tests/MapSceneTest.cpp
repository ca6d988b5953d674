// map.3Dscene: what goes into the static map (and what stays out), and that the saved scene
// opens with COpenGLScene::loadFromFile with every named part in it.
#include <dynslam/testing/TestEnv.h>
#include <dynslam/viz/MapScene.h>

#include <gtest/gtest.h>
#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>

using namespace dynslam;

namespace {

/// A 64 x 48 camera 2 m in front of a red wall (BGR 0, 0, 255), at `x` along the world x axis.
core::Frame wallFrame(std::size_t index, double x) {
  core::Frame f;
  f.index = index;
  f.t = 0.1 * static_cast<double>(index);
  f.intrinsics = {50, 50, 31.5, 23.5, 64, 48};
  f.depth = cv::Mat(48, 64, CV_32FC1, cv::Scalar(2.0f));
  f.rgb = cv::Mat(48, 64, CV_8UC3, cv::Scalar(0, 0, 255));
  f.T_world_camera = Eigen::Isometry3d(Eigen::Translation3d(x, 0, 0));
  return f;
}

/// A tracked person whose mask covers the left half of the image (columns 0-31).
void addMaskedPerson(core::Frame& f) {
  core::Track t;
  t.id = 3;
  t.state = core::TrackState::Confirmed;
  t.box = cv::Rect2f(0, 0, 32, 48);
  t.detection = 0;
  f.tracks.push_back(t);
  core::ObjectMask m;
  m.detection = 0;
  m.track = 0;
  m.roi = cv::Rect(0, 0, 32, 48);
  m.mask = cv::Mat(48, 32, CV_8UC1, cv::Scalar(255));
  m.valid = true;
  f.object_masks.push_back(m);
}

/// The builder's scene as a viewer reads it: saved, then loaded from the file.
mrpt::opengl::COpenGLScene::Ptr savedScene(const viz::MapSceneBuilder& builder) {
  const std::string path = dynslam::testing::scratchDir() + "/map.3Dscene";
  builder.save(path);
  auto scene = mrpt::opengl::COpenGLScene::Create();
  EXPECT_TRUE(scene->loadFromFile(path)) << path;
  return scene;
}

/// The scene's object called `name` as a T, null when there is none of that type.
template <class T>
std::shared_ptr<T> named(mrpt::opengl::COpenGLScene& scene, const std::string& name) {
  return std::dynamic_pointer_cast<T>(scene.getByName(name));
}

viz::MapSceneOptions everyPixel() {
  viz::MapSceneOptions o;
  o.every_n_frames = 1;
  o.pixel_stride = 1;
  return o;
}

}  // namespace

TEST(MapScene, ObjectPixelsStayOutOfTheStaticMap) {
  viz::MapSceneBuilder builder(everyPixel());
  core::Frame f = wallFrame(0, 0.0);
  addMaskedPerson(f);
  builder.addFrame(f);
  auto cloud = named<mrpt::opengl::CPointCloudColoured>(*savedScene(builder), viz::kStaticMapName);
  ASSERT_TRUE(cloud) << "no CPointCloudColoured named " << viz::kStaticMapName;
  ASSERT_GT(cloud->size(), 100u);
  EXPECT_EQ(cloud->size(), builder.pointCount());
  // 5 cm voxels on a wall sampled every 4 cm: fewer points than samples (32 x 48 unmasked).
  EXPECT_LT(cloud->size(), 32u * 48u);
  for (size_t i = 0; i < cloud->size(); ++i) {
    const auto p = cloud->getPoint3Df(i);
    const auto c = cloud->getPointColor(i);
    // Columns 32.. (grown by 2 px) start at x = (34 - 31.5) / 50 * 2 = 0.1 m; voxel means
    // within a voxel of that.
    ASSERT_GT(p.x, 0.05f) << "a masked pixel reached the map, point " << i;
    ASSERT_NEAR(p.z, 2.0f, 1e-4f);
    ASSERT_EQ(c.R, 255);
    ASSERT_EQ(c.G, 0);
  }
}

TEST(MapScene, ACoastingTracksBoxIsKeptOutAndARevisitedWallAddsNoPoints) {
  viz::MapSceneBuilder builder(everyPixel());
  core::Frame f = wallFrame(0, 0.0);
  core::Track coasting;
  coasting.id = 5;
  coasting.state = core::TrackState::Confirmed;
  coasting.box = cv::Rect2f(0, 0, 32, 48);  // no detection, no mask this frame
  f.tracks.push_back(coasting);
  builder.addFrame(f);
  const size_t once = builder.pointCount();
  viz::MapSceneBuilder full(everyPixel());
  full.addFrame(wallFrame(0, 0.0));
  EXPECT_LT(once, full.pointCount() * 0.6) << "the left half stayed out";
  const size_t before = full.pointCount();
  full.addFrame(wallFrame(1, 0.0));
  EXPECT_EQ(full.pointCount(), before) << "same wall, same voxels";
}

TEST(MapScene, ALongTrajectoryKeepsItsExtentWithinTheTrackPointLimit) {
  viz::MapSceneOptions options;
  options.every_n_frames = 100;
  options.max_track_points = 8;
  viz::MapSceneBuilder builder(options);
  for (std::size_t i = 0; i < 50; ++i) {
    builder.addFrame(wallFrame(i, 0.1 * static_cast<double>(i)));
    ASSERT_LE(builder.cameraPoses(), 8u) << "after frame " << i;
  }
  EXPECT_GE(builder.cameraPoses(), 4u);
  auto camera = named<mrpt::opengl::CSetOfLines>(*savedScene(builder), viz::kCameraTrajectoryName);
  ASSERT_TRUE(camera);
  double x0, y0, z0, x1, y1, z1;
  camera->getLineByIndex(0, x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x0, 0.0, 1e-6) << "the first pose stays";
  camera->getLineByIndex(camera->getLineCount() - 1, x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x1, 4.9, 1e-6) << "the newest pose stays";
  for (std::size_t i = 0; i < camera->getLineCount(); ++i) {
    camera->getLineByIndex(i, x0, y0, z0, x1, y1, z1);
    EXPECT_GT(x1, x0) << "in order, segment " << i;
  }
}

TEST(MapScene, SavedSceneHoldsTheTrajectoryAndEveryObjectTrack) {
  viz::MapSceneOptions options;
  options.every_n_frames = 2;
  viz::MapSceneBuilder builder(options);
  for (std::size_t i = 0; i < 5; ++i) {
    core::Frame f = wallFrame(i, 0.1 * static_cast<double>(i));
    f.object_poses.push_back({7, Eigen::Isometry3d(Eigen::Translation3d(0.2 * i, 0, 1.5))});
    if (i == 4) f.object_poses.push_back({9, Eigen::Isometry3d::Identity()});
    builder.addFrame(f);
  }
  core::Frame unposed = wallFrame(5, 0.0);
  unposed.T_world_camera.reset();
  builder.addFrame(unposed);
  EXPECT_EQ(builder.cameraPoses(), 5u);
  EXPECT_EQ(builder.objectTracks(), 2u);

  const auto scene = savedScene(builder);
  auto camera = named<mrpt::opengl::CSetOfLines>(*scene, viz::kCameraTrajectoryName);
  ASSERT_TRUE(camera);
  ASSERT_EQ(camera->getLineCount(), 4u) << "5 poses, 4 segments";
  double x0, y0, z0, x1, y1, z1;
  camera->getLineByIndex(3, x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x1, 0.4, 1e-6);
  auto seven = named<mrpt::opengl::CSetOfLines>(*scene, viz::objectTrackName(7));
  ASSERT_TRUE(seven) << viz::objectTrackName(7);
  EXPECT_EQ(seven->getLineCount(), 4u);
  seven->getLineByIndex(3, x0, y0, z0, x1, y1, z1);
  EXPECT_NEAR(x1, 0.8, 1e-6);
  EXPECT_NEAR(z1, 1.5, 1e-6);
  auto nine = named<mrpt::opengl::CSetOfLines>(*scene, viz::objectTrackName(9));
  ASSERT_TRUE(nine) << "an object seen once is still in the scene";
  EXPECT_EQ(nine->getLineCount(), 1u);
  EXPECT_NE(seven->getColor_u8(), nine->getColor_u8()) << "one colour per object";
  EXPECT_TRUE(named<mrpt::opengl::CPointCloudColoured>(*scene, viz::kStaticMapName));
}

TEST(MapScene, UnwritablePathIsNamed) {
  viz::MapSceneBuilder builder;
  try {
    builder.save("/nonexistent-dir/map.3Dscene");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/map.3Dscene"), std::string::npos);
  }
}

TEST(MapScene, TheStaticMapStopsGrowingAtMaxPoints) {
  dynslam::viz::MapSceneOptions options;
  options.every_n_frames = 1;
  options.max_points = 50;
  dynslam::viz::MapSceneBuilder builder(options);
  for (int k = 0; k < 5; ++k) {
    dynslam::core::Frame f;
    f.index = k;
    f.t = k / 30.0;
    f.depth = cv::Mat(48, 64, CV_32FC1, cv::Scalar(2.0f + 0.5f * k));  // a new wall each frame
    f.intrinsics = {50, 50, 32, 24, 64, 48};
    f.T_world_camera = Eigen::Isometry3d::Identity();
    builder.addFrame(f);
  }
  EXPECT_EQ(builder.pointCount(), 50u);
  EXPECT_GT(builder.pointsRefused(), 0u);
}

// A person's pixels a missed detection let in are seen in one frame: with min_frames = 2 the map
// subscribers get (staticPoints) leaves them out, while the wall seen twice stays; the saved
// scene keeps both.
TEST(MapScene, PointsSeenInOneFrameOnlyAreLeftOutOfTheSubscribersMap) {
  viz::MapSceneOptions o = everyPixel();
  o.min_frames = 2;
  viz::MapSceneBuilder builder(o);
  core::Frame first = wallFrame(0, 0.0);
  addMaskedPerson(first);  // the left half masked in the first frame ...
  builder.addFrame(first);
  builder.addFrame(wallFrame(1, 0.0));  // ... and not in the second
  const auto map = builder.staticPoints();
  ASSERT_GT(map->size(), 100u);
  EXPECT_LT(map->size(), builder.pointCount());  // the left half, seen once, is left out
  for (std::size_t i = 0; i < map->size(); ++i) {
    float x, y, z;
    map->getPoint(i, x, y, z);
    ASSERT_GT(x, 0.05f) << "a voxel seen in one frame only, point " << i;
  }
  auto cloud = named<mrpt::opengl::CPointCloudColoured>(*savedScene(builder), viz::kStaticMapName);
  ASSERT_TRUE(cloud);
  EXPECT_EQ(cloud->size(), builder.pointCount());
}
