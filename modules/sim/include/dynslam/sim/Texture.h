#pragma once
// Procedural textures rich in corners (so Shi-Tomasi/KLT find real features), generated from a
// seed so the same ini gives the same pixels.
#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dynslam::sim {

/// What a texture should look like. Each kind has its own generator (bricks, posters with
/// rectangles and text-like strokes, checker, floor tiles, asphalt, car paint, clothing, skin).
enum class TextureKind { Bricks, Posters, Checker, Tiles, Asphalt, CarPaint, Clothing, Skin, Wood };

/// Parses "bricks", "posters", "checker", "tiles", "asphalt", "car_paint" (or "carpaint"),
/// "clothing", "skin", "wood" (throws std::invalid_argument naming the text otherwise).
TextureKind parseTextureKind(const std::string& name);

/// The name parseTextureKind() accepts for `kind`.
std::string textureKindName(TextureKind kind);

struct Texture {
  cv::Mat image;  ///< CV_8UC3 BGR, power-of-two size so wrapping is a mask
};

/// A texture of `kind`, `size` x `size` pixels, from `seed` (same seed -> same pixels). The
/// pattern tiles seamlessly: it is drawn on a torus, so a wall can repeat it without visible
/// seams. `size` must be a power of two >= 32 (throws std::invalid_argument otherwise).
Texture makeTexture(TextureKind kind, uint64_t seed, int size = 256);

/// One level of a texture's mip pyramid, packed for the rasterizer: texel (x, y) is
/// texels[y * width + x] = B | G << 8 | R << 16, so one load fetches all three channels.
struct MipLevel {
  int width = 0, height = 0;  ///< powers of two
  std::vector<uint32_t> texels;
};

class TextureLibrary {
 public:
  /// Returns the index triangles refer to. Builds the mip pyramid (2 x 2 box averages down to
  /// one texel) the rasterizer samples, so a far floor is filtered like a camera would instead
  /// of aliasing into flickering false corners. Throws std::invalid_argument unless the image
  /// is CV_8UC3 with power-of-two sides.
  int add(Texture texture);
  const Texture& at(int index) const { return textures_.at(index); }
  size_t size() const { return textures_.size(); }
  /// Level 0 is the full-size image.
  const std::vector<MipLevel>& mipLevels(int index) const { return mip_levels_.at(index); }

 private:
  std::vector<Texture> textures_;
  std::vector<std::vector<MipLevel>> mip_levels_;
};

}  // namespace dynslam::sim
