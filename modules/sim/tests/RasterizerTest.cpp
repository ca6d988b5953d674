// Geometry of the rasterizer against closed-form answers: projection, exact depth on planes,
// occlusion and labels, near-plane clipping, the fill rule, perspective-correct texturing.
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>

#include <cmath>

namespace dynslam::sim {
namespace {

using Eigen::Vector3d;

// One flat grey texture: geometry tests look at depth and labels only.
TextureLibrary flatLibrary() {
  TextureLibrary library;
  library.add({cv::Mat(32, 32, CV_8UC3, cv::Scalar(100, 150, 200))});
  return library;
}

// A rectangle centred at `centre` (camera frame) with half-extents along unit axes a1, a2,
// moved to the world by T_world_camera.
void addCameraQuad(Mesh& mesh, const Eigen::Isometry3d& T_world_camera, const Vector3d& centre,
                   const Vector3d& a1, const Vector3d& a2, double half1, double half2,
                   uint16_t instance, int texture = 0) {
  const Vector3d origin = T_world_camera * (centre - half1 * a1 - half2 * a2);
  addQuad(mesh, origin, T_world_camera.linear() * (2 * half1 * a1),
          T_world_camera.linear() * (2 * half2 * a2), texture, instance);
}

Eigen::Isometry3d somePose() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Vector3d(0.3, 1, -0.2).normalized()).toRotationMatrix();
  T.translation() = Vector3d(1.2, -0.4, 2.5);
  return T;
}

// Depth of the plane n . X = d (camera frame) at pixel (x, y): z = d / (n . r).
double planeDepth(const Vector3d& n, double d, const core::CameraIntrinsics& k, int x, int y) {
  return d / n.dot(Vector3d((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1.0));
}

TEST(Rasterizer, KnownPointProjectsToTheDrawnPixel) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const TextureLibrary library = flatLibrary();
  const Eigen::Isometry3d pose = somePose();
  const Vector3d points[] = {{0.31, -0.17, 2.3}, {-1.1, 0.6, 3.7}, {0.02, 0.013, 0.9}};
  for (const Vector3d& p : points) {
    Mesh mesh;
    addCameraQuad(mesh, pose, p, Vector3d::UnitX(), Vector3d::UnitY(), 0.01 * p.z(), 0.01 * p.z(),
                  7);
    RenderOutput out;
    render(mesh, library, k, pose, out);
    double sum_x = 0, sum_y = 0;
    int count = 0;
    for (int y = 0; y < k.height; ++y)
      for (int x = 0; x < k.width; ++x)
        if (out.label.at<uint16_t>(y, x) == 7) sum_x += x, sum_y += y, ++count;
    ASSERT_GT(count, 4);
    const double u = k.fx * p.x() / p.z() + k.cx, v = k.fy * p.y() / p.z() + k.cy;
    EXPECT_NEAR(sum_x / count, u, 0.5) << p.transpose();
    EXPECT_NEAR(sum_y / count, v, 0.5) << p.transpose();
    EXPECT_EQ(out.label.at<uint16_t>(std::lround(v), std::lround(u)), 7);
  }
}

TEST(Rasterizer, DepthOfAFrontoParallelPlaneIsExact) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  Mesh mesh;
  addCameraQuad(mesh, pose, {0, 0, 2.5}, Vector3d::UnitX(), Vector3d::UnitY(), 5, 5, 0);
  RenderOutput out;
  render(mesh, flatLibrary(), k, pose, out);
  double worst = 0;
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x)
      worst = std::max(worst, std::abs(out.depth.at<float>(y, x) - 2.5));
  EXPECT_LT(worst, 1e-4);
}

TEST(Rasterizer, DepthOfATiltedPlaneIsExactAtEveryPixel) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  const Vector3d n = Vector3d(0.4, -0.3, -1).normalized(), centre(0.1, 0.2, 3.0);
  const Vector3d a1 = n.unitOrthogonal(), a2 = n.cross(a1);
  Mesh mesh;
  addCameraQuad(mesh, pose, centre, a1, a2, 5, 5, 0);
  RenderOutput out;
  render(mesh, flatLibrary(), k, pose, out);
  double worst = 0;
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      const double expected = planeDepth(n, n.dot(centre), k, x, y);
      worst = std::max(worst, std::abs(out.depth.at<float>(y, x) - expected));
    }
  EXPECT_LT(worst, 1e-4);
}

TEST(Rasterizer, NearQuadHidesFarQuadWhateverTheOrder) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  for (bool near_first : {true, false}) {
    Mesh mesh;
    const auto add_near = [&] {
      addCameraQuad(mesh, pose, {0, 0, 2}, Vector3d::UnitX(), Vector3d::UnitY(), 0.4, 0.3, 1);
    };
    if (near_first) add_near();
    addCameraQuad(mesh, pose, {0, 0, 4}, Vector3d::UnitX(), Vector3d::UnitY(), 5, 5, 2);
    if (!near_first) add_near();
    RenderOutput out;
    render(mesh, flatLibrary(), k, pose, out);
    // The near quad spans x in cx +- 105 px, y in cy +- 78.75 px.
    for (int y = 0; y < k.height; y += 3)
      for (int x = 0; x < k.width; x += 3) {
        const bool in_near = std::abs(x - k.cx) < 104 && std::abs(y - k.cy) < 78;
        const bool out_near = std::abs(x - k.cx) > 106 || std::abs(y - k.cy) > 80;
        if (in_near) {
          ASSERT_EQ(out.label.at<uint16_t>(y, x), 1) << x << "," << y;
          ASSERT_NEAR(out.depth.at<float>(y, x), 2.0, 1e-5);
        } else if (out_near) {
          ASSERT_EQ(out.label.at<uint16_t>(y, x), 2) << x << "," << y;
          ASSERT_NEAR(out.depth.at<float>(y, x), 4.0, 1e-5);
        }
      }
  }
}

TEST(Rasterizer, BoxInstanceLabelsAndNearestFaceDepth) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  Mesh mesh;
  addQuad(mesh, {-5, -5, 6}, {10, 0, 0}, {0, 10, 0}, 0, 0);  // static wall: label 0
  Eigen::Isometry3d T_box = Eigen::Isometry3d::Identity();
  T_box.translation() = Vector3d(-0.5, 0, 3);
  addBox(mesh, T_box, {0.2, 0.2, 0.2}, 0, 9);
  T_box.translation() = Vector3d(0.5, 0, 3);
  addBox(mesh, T_box, {0.2, 0.2, 0.2}, 0, 12);
  RenderOutput out;
  render(mesh, flatLibrary(), k, Eigen::Isometry3d::Identity(), out);
  const auto pixel = [&](const Vector3d& p) {
    return cv::Point(std::lround(k.fx * p.x() / p.z() + k.cx),
                     std::lround(k.fy * p.y() / p.z() + k.cy));
  };
  EXPECT_EQ(out.label.at<uint16_t>(pixel({-0.5, 0, 2.8})), 9);
  EXPECT_NEAR(out.depth.at<float>(pixel({-0.5, 0, 2.8})), 2.8, 1e-5);  // the front face
  EXPECT_EQ(out.label.at<uint16_t>(pixel({0.5, 0.1, 2.8})), 12);
  EXPECT_EQ(out.label.at<uint16_t>(pixel({0, 0, 3})), 0);
  EXPECT_NEAR(out.depth.at<float>(pixel({0, 0, 6})), 6.0, 1e-5);
  EXPECT_EQ(out.label.at<uint16_t>(pixel({0, 1, 6})), 0);
}

TEST(Rasterizer, NearPlaneCutsTheCrossingPartAndKeepsTheRest) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  const Vector3d n = Vector3d(0.5, 0.2, -1).normalized(), centre(0, 0, 2.0);
  const Vector3d a1 = n.unitOrthogonal(), a2 = n.cross(a1);
  Mesh mesh;
  addCameraQuad(mesh, pose, centre, a1, a2, 6, 6, 3);
  RasterizerOptions options;
  options.near_plane = 1.8;  // cuts the plane through the middle of the image
  RenderOutput out;
  render(mesh, flatLibrary(), k, pose, out, options);
  int drawn = 0, cut = 0;
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      const double expected = planeDepth(n, n.dot(centre), k, x, y);
      const float depth = out.depth.at<float>(y, x);
      if (expected > 1.8 + 1e-3) {
        ASSERT_NEAR(depth, expected, 1e-4) << x << "," << y;
        ASSERT_EQ(out.label.at<uint16_t>(y, x), 3);
        ++drawn;
      } else if (expected < 1.8 - 1e-3) {
        ASSERT_EQ(depth, 0.0f) << x << "," << y;
        ASSERT_EQ(out.label.at<uint16_t>(y, x), 0);
        ASSERT_EQ(out.rgb.at<cv::Vec3b>(y, x), options.background);
        ++cut;
      }
    }
  EXPECT_GT(drawn, 50000);
  EXPECT_GT(cut, 50000);
}

TEST(Rasterizer, WallWithVerticesBehindTheCameraDrawsOnlyItsVisiblePart) {
  // Side wall X = 1 (camera frame) from 2 m behind the camera to 5 m in front of it: without
  // clipping the vertices behind would project mirrored across the image.
  const core::CameraIntrinsics k = testing::vgaCamera();
  Mesh mesh;
  addQuad(mesh, {1, -2, -2}, {0, 4, 0}, {0, 0, 7}, 0, 4);
  RenderOutput out;
  render(mesh, flatLibrary(), k, Eigen::Isometry3d::Identity(), out);
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      const double z = x > k.cx ? k.fx / (x - k.cx) : 1e9;    // where the ray meets X = 1
      const double height = std::abs(z * (y - k.cy) / k.fy);  // |Y| there; the wall has 2
      const float depth = out.depth.at<float>(y, x);
      if (z < 5 - 1e-3 && height < 2 - 1e-3) {
        ASSERT_NEAR(depth, z, 1e-4 * z) << x << "," << y;
      } else if (z > 5 + 1e-3 || height > 2 + 1e-3) {
        ASSERT_EQ(depth, 0.0f) << x << "," << y;
      }
    }
}

// Renders each triangle of `mesh` alone and counts, per pixel, how many drew it.
cv::Mat coverageCount(const Mesh& mesh, const core::CameraIntrinsics& k,
                      const Eigen::Isometry3d& pose) {
  const TextureLibrary library = flatLibrary();
  cv::Mat count(k.height, k.width, CV_32SC1, cv::Scalar(0));
  RenderOutput out;
  for (Triangle triangle : mesh) {
    triangle.instance = 1;
    render({triangle}, library, k, pose, out);
    cv::Mat drawn;
    cv::compare(out.label, 1, drawn, cv::CMP_EQ);
    cv::add(count, 1, count, drawn);
  }
  return count;
}

TEST(Rasterizer, TrianglesSharingEdgesCoverEveryPixelExactlyOnce) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  // A tilted, rotated 9 x 7 grid of quads (126 triangles, diagonals of many slopes) plus a fan
  // of 16 triangles around one vertex.
  const Vector3d n = Vector3d(0.2, -0.35, -1).normalized(), centre(0.05, -0.1, 3.0);
  const Vector3d a1 = n.unitOrthogonal(), a2 = n.cross(a1);
  const Vector3d b1 = std::cos(0.3) * a1 + std::sin(0.3) * a2, b2 = n.cross(b1);
  Mesh mesh;
  const double cell = 0.15;
  const Vector3d corner = centre - 4.5 * cell * b1 - 3.5 * cell * b2;
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 9; ++i)
      addQuad(mesh, pose * (corner + (i * cell) * b1 + (j * cell) * b2),
              pose.linear() * (cell * b1), pose.linear() * (cell * b2), 0, 1);
  const Vector3d hub = centre + 1.0 * b1;
  for (int i = 0; i < 16; ++i) {
    const auto rim = [&](int j) {
      const double angle = 2 * M_PI * j / 16;
      return pose * (hub + 0.25 * (std::cos(angle) * b1 + std::sin(angle) * b2));
    };
    const Eigen::Vector2f zero = Eigen::Vector2f::Zero();
    mesh.push_back({{pose * hub, rim(i), rim(i + 1)}, {zero, zero, zero}, 0, 1});
  }
  const cv::Mat count = coverageCount(mesh, k, pose);
  double max_count;
  cv::minMaxLoc(count, nullptr, &max_count);
  EXPECT_EQ(max_count, 1) << "a pixel was drawn by two triangles";
  // Every pixel whose centre is inside the grid (not within 0.01 px of its border) is drawn.
  const auto project = [&](const Vector3d& p) {
    return Eigen::Vector2d(k.fx * p.x() / p.z() + k.cx, k.fy * p.y() / p.z() + k.cy);
  };
  const Eigen::Vector2d q[4] = {project(corner), project(corner + 9 * cell * b1),
                                project(corner + 9 * cell * b1 + 7 * cell * b2),
                                project(corner + 7 * cell * b2)};
  int inside = 0;
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      double min_distance = 1e9, sign = 0;
      for (int e = 0; e < 4; ++e) {
        const Eigen::Vector2d edge = q[(e + 1) % 4] - q[e], to = Eigen::Vector2d(x, y) - q[e];
        const double cross = (edge.x() * to.y() - edge.y() * to.x()) / edge.norm();
        if (e == 0) sign = cross > 0 ? 1 : -1;
        min_distance = std::min(min_distance, sign * cross);
      }
      if (min_distance > 0.01) {
        ++inside;
        ASSERT_EQ(count.at<int>(y, x), 1) << x << "," << y;
      }
    }
  EXPECT_GT(inside, 20000);
}

TEST(Rasterizer, EdgesThroughPixelCentresFollowTheFillRule) {
  // 100 px squares with corners on pixel centres (z = 5.25 m: 100 px per metre): their edges
  // and diagonals pass exactly through pixel centres, which the fill rule gives to exactly one
  // side. A 3 x 2 block of them covers exactly 300 x 200 pixels, each once.
  const core::CameraIntrinsics k = testing::vgaCamera();
  const auto at = [&](double px, double py) {
    return Vector3d((px - k.cx) / 100, (py - k.cy) / 100, 5.25);
  };
  Mesh mesh;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
      addQuad(mesh, at(100 + 100 * i, 100 + 100 * j), {1, 0, 0}, {0, 1, 0}, 0, 1);
  const cv::Mat count = coverageCount(mesh, k, Eigen::Isometry3d::Identity());
  double max_count;
  cv::minMaxLoc(count, nullptr, &max_count);
  EXPECT_EQ(max_count, 1);
  EXPECT_EQ(cv::countNonZero(count), 300 * 200);
}

TEST(Rasterizer, SharedEdgesStayWatertightWhereClipped) {
  // A floor of 2 m quads seen from 1 m above, looking down steeply, with a 1.2 m near plane:
  // many triangles are cut by the near plane and by the guard band, and the cut edges of
  // neighbours must still meet exactly.
  const core::CameraIntrinsics k = testing::vgaCamera();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(-1.0, Vector3d::UnitX()).toRotationMatrix();  // look down
  Mesh mesh;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 10; ++i)
      addQuad(mesh, {-10.0 + 2 * i, 1, -2.0 + 2 * j}, {2, 0, 0}, {0, 0, 2}, 0, 1);
  RasterizerOptions options;
  options.near_plane = 1.2;
  const TextureLibrary library = flatLibrary();
  cv::Mat count(k.height, k.width, CV_32SC1, cv::Scalar(0));
  RenderOutput out;
  for (const Triangle& triangle : mesh) {
    render({triangle}, library, k, pose, out, options);
    cv::add(count, 1, count, out.label == 1);
  }
  int drawn = 0, cut = 0;
  for (int y = 0; y < k.height; ++y)
    for (int x = 0; x < k.width; ++x) {
      const Vector3d ray = pose.linear() * Vector3d((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1);
      const double depth = ray.y() > 0 ? 1.0 / ray.y() : 1e9;  // the floor is at world y = 1
      const Vector3d hit = depth * ray;
      const bool on_grid = std::abs(hit.x()) < 9.99 && hit.z() > -1.99 && hit.z() < 9.99;
      if (on_grid && depth > 1.2 * 1.001) {
        ASSERT_EQ(count.at<int>(y, x), 1) << x << "," << y;
        ++drawn;
      } else if (!on_grid || depth < 1.2 * 0.999) {
        ASSERT_LE(count.at<int>(y, x), 1) << x << "," << y;
        cut += depth < 1.2 * 0.999;
      }
    }
  EXPECT_GT(drawn, 100000);
  EXPECT_GT(cut, 10000);
}

TEST(Rasterizer, TextureIsPerspectiveCorrect) {
  // Texel (i, j) of a 32 x 32 texture has colour (8 i, 8 j, 77): the colour at a pixel says
  // which texel was sampled, to compare with the texel of the exact ray-plane hit.
  cv::Mat image(32, 32, CV_8UC3);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) image.at<cv::Vec3b>(j, i) = cv::Vec3b(8 * i, 8 * j, 77);
  TextureLibrary library;
  library.add({image});
  const core::CameraIntrinsics k = testing::vgaCamera();
  const Eigen::Isometry3d pose = somePose();
  const Vector3d n = Vector3d(0.6, -0.2, -1).normalized(), centre(0, 0, 3.0);
  const Vector3d a1 = n.unitOrthogonal(), a2 = n.cross(a1);
  Mesh mesh;
  const double scale = 0.5;  // metres per texture repeat
  const Vector3d origin = centre - 4 * a1 - 4 * a2;
  addQuad(mesh, pose * origin, pose.linear() * (8 * a1), pose.linear() * (8 * a2), 0, 1, scale);
  RasterizerOptions options;
  options.bilinear = false;
  options.mipmaps = false;
  RenderOutput out;
  render(mesh, library, k, pose, out, options);
  int checked = 0;
  for (int y = 0; y < k.height; y += 2)
    for (int x = 0; x < k.width; x += 2) {
      const Vector3d ray((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1);
      const Vector3d hit = ray * (n.dot(centre) / n.dot(ray));
      const double along1 = (hit - origin).dot(a1), along2 = (hit - origin).dot(a2);
      if (std::min(along1, along2) < 0.01 || std::max(along1, along2) > 7.99) continue;
      const double u = along1 / scale * 32, v = along2 / scale * 32;
      const double du = u - std::floor(u), dv = v - std::floor(v);
      if (du < 0.05 || du > 0.95 || dv < 0.05 || dv > 0.95) continue;  // texel borders
      const auto i = static_cast<int>(std::floor(u)) & 31, j = static_cast<int>(std::floor(v)) & 31;
      ASSERT_EQ(out.rgb.at<cv::Vec3b>(y, x), cv::Vec3b(8 * i, 8 * j, 77)) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 40000);
}

TEST(Rasterizer, EmptySceneIsBackgroundAndBadTextureThrows) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  RenderOutput out;
  RasterizerOptions options;
  options.background = {1, 2, 3};
  render({}, flatLibrary(), k, Eigen::Isometry3d::Identity(), out, options);
  EXPECT_EQ(cv::countNonZero(out.depth), 0);
  EXPECT_EQ(cv::countNonZero(out.label), 0);
  EXPECT_EQ(out.rgb.at<cv::Vec3b>(100, 100), cv::Vec3b(1, 2, 3));
  Mesh mesh;
  addQuad(mesh, {-1, -1, 2}, {2, 0, 0}, {0, 2, 0}, 5, 0);
  EXPECT_THROW(render(mesh, flatLibrary(), k, Eigen::Isometry3d::Identity(), out),
               std::out_of_range);
}

TEST(Rasterizer, KeptFrameIsNotOverwrittenByTheNextRender) {
  const core::CameraIntrinsics k = testing::vgaCamera();
  Mesh mesh;
  addQuad(mesh, {-5, -5, 2}, {10, 0, 0}, {0, 10, 0}, 0, 0);
  RenderOutput out;
  render(mesh, flatLibrary(), k, Eigen::Isometry3d::Identity(), out);
  const cv::Mat kept = out.depth;  // shares the buffer
  render({}, flatLibrary(), k, Eigen::Isometry3d::Identity(), out);
  EXPECT_FLOAT_EQ(kept.at<float>(240, 320), 2.0f);
  EXPECT_EQ(out.depth.at<float>(240, 320), 0.0f);
}

}  // namespace
}  // namespace dynslam::sim
