// Procedural textures: reproducible from the seed, seamless, and rich in well-spread corners
// once rendered the way the simulator shows them.
#include <dynslam/sim/Rasterizer.h>
#include <dynslam/sim/Texture.h>
#include <dynslam/testing/SyntheticRoom.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <dynslam/testing/TestEnv.h>

namespace dynslam::sim {
namespace {

const TextureKind kAllKinds[] = {TextureKind::Bricks,   TextureKind::Posters, TextureKind::Checker,
                                 TextureKind::Tiles,    TextureKind::Asphalt, TextureKind::CarPaint,
                                 TextureKind::Clothing, TextureKind::Skin,    TextureKind::Wood};

bool identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(Texture, SameSeedSameBytesOtherSeedOtherBytes) {
  for (TextureKind kind : kAllKinds) {
    const Texture a = makeTexture(kind, 42), b = makeTexture(kind, 42), c = makeTexture(kind, 43);
    ASSERT_EQ(a.image.type(), CV_8UC3);
    ASSERT_EQ(a.image.size(), cv::Size(256, 256));
    EXPECT_TRUE(identical(a.image, b.image)) << textureKindName(kind);
    EXPECT_FALSE(identical(a.image, c.image)) << textureKindName(kind);
  }
  for (int size : {32, 64, 1024})
    for (TextureKind kind : kAllKinds)
      EXPECT_EQ(makeTexture(kind, 1, size).image.size(), cv::Size(size, size));
  EXPECT_THROW(makeTexture(TextureKind::Bricks, 1, 100), std::invalid_argument);
}

TEST(Texture, KindNamesRoundTrip) {
  for (TextureKind kind : kAllKinds) EXPECT_EQ(parseTextureKind(textureKindName(kind)), kind);
  EXPECT_EQ(parseTextureKind("CarPaint"), TextureKind::CarPaint);
  EXPECT_THROW(parseTextureKind("marble"), std::invalid_argument);
}

TEST(Texture, TilesWithoutSeams) {
  // Across the wrap (last column -> first, last row -> first) the image changes no more than
  // across the strongest edge inside it: content continues over the border and the blur
  // wrapped. (Grid patterns legitimately have an edge there, so the mean step is no bound.)
  for (TextureKind kind : kAllKinds) {
    const cv::Mat image = makeTexture(kind, 7).image;
    cv::Mat gray;
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
    gray.convertTo(gray, CV_32F);
    const int n = gray.cols;
    const auto column_step = [&](int a, int b) {
      return cv::norm(gray.col(a), gray.col(b), cv::NORM_L1) / n;
    };
    const auto row_step = [&](int a, int b) {
      return cv::norm(gray.row(a), gray.row(b), cv::NORM_L1) / n;
    };
    double max_column_step = 0, max_row_step = 0;
    for (int i = 0; i + 1 < n; ++i) {
      max_column_step = std::max(max_column_step, column_step(i, i + 1));
      max_row_step = std::max(max_row_step, row_step(i, i + 1));
    }
    EXPECT_LE(column_step(n - 1, 0), max_column_step) << textureKindName(kind);
    EXPECT_LE(row_step(n - 1, 0), max_row_step) << textureKindName(kind);
  }
}

TEST(Texture, LibraryBuildsBoxFilteredMipLevels) {
  TextureLibrary library;
  const int index = library.add(makeTexture(TextureKind::Checker, 3, 64));
  const std::vector<MipLevel>& levels = library.mipLevels(index);
  ASSERT_EQ(levels.size(), 7u);  // 64, 32, ..., 1
  EXPECT_EQ(levels.back().width, 1);
  const cv::Mat& image = library.at(index).image;
  for (int c = 0; c < 3; ++c) {
    int sum = 0;
    for (int y = 0; y < 2; ++y)
      for (int x = 2; x < 4; ++x) sum += image.at<cv::Vec3b>(y, x)[c];
    EXPECT_EQ(static_cast<int>((levels[1].texels[1] >> (8 * c)) & 0xFF), (sum + 2) / 4);
    EXPECT_EQ(static_cast<int>((levels[0].texels[64 * 5 + 9] >> (8 * c)) & 0xFF),
              image.at<cv::Vec3b>(5, 9)[c]);
  }
  EXPECT_THROW(library.add({cv::Mat(48, 64, CV_8UC3)}), std::invalid_argument);
  EXPECT_THROW(library.add({cv::Mat(64, 64, CV_8UC1)}), std::invalid_argument);
}

struct CornerStats {
  int corners = 0;
  int cells_with_corners = 0;  // of the 4 x 4 grid
};

// A wall of `kind` fronto-parallel at 2 m filling a 640 x 480 view (texture_scale 1 m), and
// Shi-Tomasi corners as a KLT front end would pick them.
CornerStats cornersOnWall(TextureKind kind, uint64_t seed, cv::Mat* rendering = nullptr) {
  TextureLibrary library;
  library.add(makeTexture(kind, seed));
  Mesh mesh;
  addQuad(mesh, {-2.1, -1.3, 2.0}, {4.2, 0, 0}, {0, 2.6, 0}, 0, 0);
  RenderOutput out;
  const core::CameraIntrinsics k = testing::vgaCamera();
  render(mesh, library, k, Eigen::Isometry3d::Identity(), out);
  cv::Mat gray;
  cv::cvtColor(out.rgb, gray, cv::COLOR_BGR2GRAY);
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(gray, corners, 5000, 0.01, 8);
  CornerStats stats;
  stats.corners = static_cast<int>(corners.size());
  bool cell[16] = {};
  for (const cv::Point2f& c : corners)
    cell[std::min(3, static_cast<int>(c.y * 4 / k.height)) * 4 +
         std::min(3, static_cast<int>(c.x * 4 / k.width))] = true;
  for (bool has : cell) stats.cells_with_corners += has;
  if (rendering != nullptr) *rendering = out.rgb;
  return stats;
}

TEST(Texture, WallsCarsAndClothesAreRichInWellSpreadCorners) {
  const std::string folder = testing::scratchDir();
  for (TextureKind kind : kAllKinds) {
    for (uint64_t seed : {1u, 2u, 3u}) {
      cv::Mat rendering;
      const CornerStats stats = cornersOnWall(kind, seed, &rendering);
      std::cout << textureKindName(kind) << " seed " << seed << ": " << stats.corners
                << " corners in " << stats.cells_with_corners << "/16 cells\n";
      if (seed == 1) cv::imwrite(folder + "/" + textureKindName(kind) + ".png", rendering);
      if (kind == TextureKind::Skin) {
        // Skin is smooth by nature; freckles and moles still give a few features.
        EXPECT_GE(stats.corners, 30) << "skin seed " << seed;
        continue;
      }
      EXPECT_GE(stats.corners, 150) << textureKindName(kind) << " seed " << seed;
      EXPECT_GE(stats.cells_with_corners, 12) << textureKindName(kind) << " seed " << seed;
    }
  }
  std::cout << "wall renderings in " << folder << "\n";
}

}  // namespace
}  // namespace dynslam::sim
