// Frames per second of the renderer (and renderer + sensor noise) on the scene the simulator
// is for: a textured room with shelves and three walking people, seen from a moving camera.
// Prints the numbers; asserts only that the frames are sane (timing depends on the machine).
#include <dynslam/sim/SensorNoise.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace dynslam::sim {
namespace {

using Eigen::Vector3d;

// World: z up, room [-4, 4] x [-3, 3] x [0, 3] m.
struct RoomScene {
  TextureLibrary textures;
  Mesh room;  // static part: 18 quads and 3 shelves of 7 boxes
};

RoomScene buildRoom() {
  RoomScene scene;
  const int bricks = scene.textures.add(makeTexture(TextureKind::Bricks, 1));
  const int posters = scene.textures.add(makeTexture(TextureKind::Posters, 2));
  const int tiles = scene.textures.add(makeTexture(TextureKind::Tiles, 3));
  const int checker = scene.textures.add(makeTexture(TextureKind::Checker, 4));
  const int wood = scene.textures.add(makeTexture(TextureKind::Wood, 5));
  Mesh& m = scene.room;
  // Floor and ceiling in quarters so their edges meet the wall halves vertex to vertex: a
  // vertex in the middle of another triangle's edge (T-junction) can leave pixel cracks.
  for (double x0 : {-4.0, 0.0})
    for (double y0 : {-3.0, 0.0}) {
      addQuad(m, {x0, y0, 0}, {4, 0, 0}, {0, 3, 0}, tiles, 0);
      addQuad(m, {x0, y0, 3}, {4, 0, 0}, {0, 3, 0}, checker, 0);
    }
  // Each wall in two halves with different textures, plus a poster board and a door.
  addQuad(m, {-4, -3, 0}, {4, 0, 0}, {0, 0, 3}, bricks, 0);
  addQuad(m, {0, -3, 0}, {4, 0, 0}, {0, 0, 3}, posters, 0);
  addQuad(m, {-4, 3, 0}, {4, 0, 0}, {0, 0, 3}, posters, 0);
  addQuad(m, {0, 3, 0}, {4, 0, 0}, {0, 0, 3}, bricks, 0);
  addQuad(m, {-4, -3, 0}, {0, 3, 0}, {0, 0, 3}, bricks, 0);
  addQuad(m, {-4, 0, 0}, {0, 3, 0}, {0, 0, 3}, posters, 0);
  addQuad(m, {4, -3, 0}, {0, 3, 0}, {0, 0, 3}, posters, 0);
  addQuad(m, {4, 0, 0}, {0, 3, 0}, {0, 0, 3}, bricks, 0);
  addQuad(m, {3.98, -1, 0.8}, {0, 2, 0}, {0, 0, 1.2}, posters, 0);
  addQuad(m, {-1, 2.98, 0}, {1, 0, 0}, {0, 0, 2.1}, wood, 0);
  for (int s = 0; s < 3; ++s) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(s * M_PI / 2, Vector3d::UnitZ()).toRotationMatrix();
    T.translation() = Vector3d(-3 + 2.5 * s, s == 1 ? 2.6 : -2.6, 0);
    const auto box = [&](const Vector3d& centre, const Vector3d& half) {
      Eigen::Isometry3d T_box = T;
      T_box.translation() += T.linear() * centre;
      addBox(m, T_box, half, wood, 0, 0.5);
    };
    box({-0.6, 0, 1}, {0.02, 0.2, 1});  // sides
    box({0.6, 0, 1}, {0.02, 0.2, 1});
    box({0, 0.19, 1}, {0.6, 0.01, 1});  // back
    for (int shelf = 0; shelf < 4; ++shelf) box({0, 0, 0.1 + 0.6 * shelf}, {0.58, 0.19, 0.015});
  }
  return scene;
}

// A person of 11 boxes (~130 triangles) walking along a circle, limbs swinging with the gait.
void addPerson(Mesh& mesh, double t, double radius, double phase, uint16_t instance, int clothing,
               int skin) {
  const double angle = 0.5 * t / radius + phase;
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  body.translation() = Vector3d(radius * std::cos(angle), radius * std::sin(angle), 0);
  body.linear() = Eigen::AngleAxisd(angle + M_PI / 2, Vector3d::UnitZ()).toRotationMatrix();
  const double swing = 0.5 * std::sin(2 * M_PI * 0.9 * t + phase);
  const auto part = [&](const Vector3d& joint, double pitch, const Vector3d& offset,
                        const Vector3d& half, int texture) {
    Eigen::Isometry3d T = body;
    T.translate(joint);
    T.rotate(Eigen::AngleAxisd(pitch, Vector3d::UnitY()));
    T.translate(offset);
    addBox(mesh, T, half, texture, instance, 0.5);
  };
  part({0, 0, 1.0}, 0, {0, 0, 0}, {0.1, 0.17, 0.08}, clothing);     // pelvis
  part({0, 0, 1.1}, 0, {0, 0, 0.25}, {0.11, 0.2, 0.25}, clothing);  // torso
  part({0, 0, 1.6}, 0, {0, 0, 0.12}, {0.09, 0.08, 0.12}, skin);     // head
  for (int side = -1; side <= 1; side += 2) {
    const double s = side * swing;
    part({0, side * 0.25, 1.55}, s, {0, 0, -0.15}, {0.05, 0.05, 0.15}, clothing);  // upper arm
    part({0, side * 0.25, 1.55}, s, {0, 0, -0.43}, {0.04, 0.04, 0.13}, skin);      // forearm
    part({0, side * 0.1, 0.95}, -s, {0, 0, -0.22}, {0.07, 0.07, 0.22}, clothing);  // thigh
    part({0, side * 0.1, 0.95}, -s, {0, 0, -0.68}, {0.05, 0.05, 0.24}, clothing);  // shin
  }
}

// Camera walking a loop in the room at eye height, looking ahead and a little down.
Eigen::Isometry3d cameraPose(double t) {
  const double a = 0.3 * t;
  const Vector3d position(1.5 * std::cos(a), 1.0 * std::sin(a), 1.5);
  const Vector3d forward =
      Vector3d(-std::sin(a + 0.6), std::cos(a + 0.6), -0.25 + 0.1 * std::sin(1.3 * t)).normalized();
  const Vector3d right = forward.cross(Vector3d::UnitZ()).normalized();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear().col(0) = right;
  T.linear().col(1) = forward.cross(right);
  T.linear().col(2) = forward;
  T.translation() = position;
  return T;
}

TEST(RenderSpeed, IndoorRoomWithThreePeople) {
  RoomScene scene = buildRoom();
  const int clothing[3] = {scene.textures.add(makeTexture(TextureKind::Clothing, 10)),
                           scene.textures.add(makeTexture(TextureKind::Clothing, 11)),
                           scene.textures.add(makeTexture(TextureKind::Clothing, 12))};
  const int skin = scene.textures.add(makeTexture(TextureKind::Skin, 13));
  const core::CameraIntrinsics k = testing::vgaCamera();
  const int frames = 300;
  const auto meshAt = [&](double t) {
    Mesh mesh = scene.room;
    for (int p = 0; p < 3; ++p)
      addPerson(mesh, t, 1.2 + 0.9 * p, 2.1 * p, static_cast<uint16_t>(p + 1), clothing[p], skin);
    return mesh;
  };
  std::cout << "scene: " << meshAt(0).size() << " triangles, " << k.width << "x" << k.height
            << "\n";

  const auto run = [&](int threads, bool noise) {
    RasterizerOptions options;
    options.threads = threads;
    RenderOutput out;
    std::mt19937_64 rng(1);
    int frames_with_people = 0;
    double min_coverage = 1;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
      const double t = i / 30.0;
      render(meshAt(t), scene.textures, k, cameraPose(t), out, options);
      if (noise) applyRgbdNoise(out, {}, rng);
      double max_label;
      cv::minMaxLoc(out.label, nullptr, &max_label);
      frames_with_people += max_label > 0;
      if (!noise)
        min_coverage = std::min(
            min_coverage, cv::countNonZero(out.depth) / static_cast<double>(k.width * k.height));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << (noise ? "render + noise" : "render") << ", " << threads
              << " thread(s): " << frames / seconds << " frames/s (" << 1000 * seconds / frames
              << " ms/frame)\n";
    EXPECT_GT(frames_with_people, frames / 4);
    if (!noise) {
      EXPECT_EQ(min_coverage, 1.0) << "the closed room leaves no pixel empty";
    }
  };
  run(1, false);
  run(2, false);
  run(1, true);
  run(2, true);
}

TEST(RenderSpeed, ThreadCountDoesNotChangeTheImages) {
  const RoomScene scene = buildRoom();
  const core::CameraIntrinsics k = testing::vgaCamera();
  for (double t : {0.0, 3.3, 7.1}) {
    RenderOutput one, three;
    RasterizerOptions options;
    render(scene.room, scene.textures, k, cameraPose(t), one, options);
    options.threads = 3;
    render(scene.room, scene.textures, k, cameraPose(t), three, options);
    EXPECT_EQ(cv::norm(one.rgb, three.rgb, cv::NORM_INF), 0);
    EXPECT_EQ(cv::norm(one.depth, three.depth, cv::NORM_INF), 0);
    EXPECT_EQ(cv::norm(one.label, three.label, cv::NORM_INF), 0);
  }
}

}  // namespace
}  // namespace dynslam::sim
