#include "dynslam/sim/Texture.h"

#include "TexturePainters.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace dynslam::sim {
namespace {

struct KindName {
  TextureKind kind;
  const char* name;
};
constexpr KindName kKindNames[] = {
    {TextureKind::Bricks, "bricks"},     {TextureKind::Posters, "posters"},
    {TextureKind::Checker, "checker"},   {TextureKind::Tiles, "tiles"},
    {TextureKind::Asphalt, "asphalt"},   {TextureKind::CarPaint, "car_paint"},
    {TextureKind::Clothing, "clothing"}, {TextureKind::Skin, "skin"},
    {TextureKind::Wood, "wood"}};

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

MipLevel packLevel(const cv::Mat& bgr) {
  MipLevel level;
  level.width = bgr.cols;
  level.height = bgr.rows;
  level.texels.resize(static_cast<size_t>(bgr.cols) * bgr.rows);
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* row = bgr.ptr<uchar>(y);
    for (int x = 0; x < bgr.cols; ++x)
      level.texels[static_cast<size_t>(y) * bgr.cols + x] =
          row[3 * x] | row[3 * x + 1] << 8 | static_cast<uint32_t>(row[3 * x + 2]) << 16;
  }
  return level;
}

// The next level: each texel the rounded mean of a 2 x 2 block (sides halve, down to 1).
MipLevel halve(const MipLevel& fine) {
  MipLevel coarse;
  coarse.width = std::max(1, fine.width / 2);
  coarse.height = std::max(1, fine.height / 2);
  coarse.texels.resize(static_cast<size_t>(coarse.width) * coarse.height);
  const int step_x = fine.width > 1 ? 1 : 0, step_y = fine.height > 1 ? fine.width : 0;
  for (int y = 0; y < coarse.height; ++y)
    for (int x = 0; x < coarse.width; ++x) {
      const size_t i = static_cast<size_t>(2 * y) * fine.width + 2 * x;
      const uint32_t t[4] = {fine.texels[i], fine.texels[i + step_x], fine.texels[i + step_y],
                             fine.texels[i + step_x + step_y]};
      uint32_t packed = 0;
      for (int shift = 0; shift <= 16; shift += 8) {
        uint32_t sum = 2;
        for (uint32_t texel : t) sum += (texel >> shift) & 0xFF;
        packed |= (sum / 4) << shift;
      }
      coarse.texels[static_cast<size_t>(y) * coarse.width + x] = packed;
    }
  return coarse;
}

}  // namespace

TextureKind parseTextureKind(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "carpaint") return TextureKind::CarPaint;
  for (const KindName& entry : kKindNames)
    if (lower == entry.name) return entry.kind;
  throw std::invalid_argument("unknown texture kind '" + name +
                              "' (expected bricks, posters, checker, tiles, asphalt, car_paint, "
                              "clothing, skin or wood)");
}

std::string textureKindName(TextureKind kind) {
  for (const KindName& entry : kKindNames)
    if (entry.kind == kind) return entry.name;
  throw std::invalid_argument("unknown TextureKind");
}

Texture makeTexture(TextureKind kind, uint64_t seed, int size) {
  if (size < 32 || !isPowerOfTwo(size))
    throw std::invalid_argument("texture size must be a power of two >= 32, got " +
                                std::to_string(size));
  // Mix the kind into the seed so kinds drawn from one seed are not correlated.
  detail::SeededRandom random(seed ^ (0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(kind) + 1)));
  Texture texture;
  switch (kind) {
    case TextureKind::Bricks:
      texture.image = detail::paintBricks(random, size);
      break;
    case TextureKind::Posters:
      texture.image = detail::paintPosters(random, size);
      break;
    case TextureKind::Checker:
      texture.image = detail::paintChecker(random, size);
      break;
    case TextureKind::Tiles:
      texture.image = detail::paintTiles(random, size);
      break;
    case TextureKind::Asphalt:
      texture.image = detail::paintAsphalt(random, size);
      break;
    case TextureKind::CarPaint:
      texture.image = detail::paintCarPaint(random, size);
      break;
    case TextureKind::Clothing:
      texture.image = detail::paintClothing(random, size);
      break;
    case TextureKind::Skin:
      texture.image = detail::paintSkin(random, size);
      break;
    case TextureKind::Wood:
      texture.image = detail::paintWood(random, size);
      break;
  }
  return texture;
}

int TextureLibrary::add(Texture texture) {
  const cv::Mat& image = texture.image;
  if (image.type() != CV_8UC3 || !isPowerOfTwo(image.cols) || !isPowerOfTwo(image.rows))
    throw std::invalid_argument(
        "TextureLibrary::add: the image must be CV_8UC3 with power-of-two sides");
  std::vector<MipLevel> levels{packLevel(image)};
  while (levels.back().width > 1 || levels.back().height > 1)
    levels.push_back(halve(levels.back()));
  textures_.push_back(std::move(texture));
  mip_levels_.push_back(std::move(levels));
  return static_cast<int>(textures_.size()) - 1;
}

}  // namespace dynslam::sim
