// Textures of the static world: walls, floors, furniture and roads. Every generator scales its
// features with the texture size (`k` = size / 256) and puts corners everywhere: brick and tile
// corners, poster contents, knots and nails, road speckle, so a 256 px texture seen 1:1 (a wall
// at 2 m with texture_scale 1 m and f = 525 px) gives hundreds of well-spread Shi-Tomasi
// corners.
#include "TexturePainters.h"

#include <cmath>
#include <string>

namespace dynslam::sim::detail {
namespace {

int scaled(double pixels_at_256, int size) {
  return std::max(1, static_cast<int>(std::lround(pixels_at_256 * size / 256.0)));
}

cv::Point randomPoint(SeededRandom& random, int size) {
  return {random.uniformInt(0, size - 1), random.uniformInt(0, size - 1)};
}

std::string randomWord(SeededRandom& random, int min_length, int max_length) {
  static const char kGlyphs[] = "ABCDEFGHJKLMNPRSTUVWXYZ0123456789";
  std::string word(random.uniformInt(min_length, max_length), ' ');
  for (char& c : word) c = kGlyphs[random.uniformInt(0, sizeof(kGlyphs) - 2)];
  return word;
}

// Text, bars, stripes and a logo inside `poster` (what makes posters corner-rich).
void paintPosterContents(WrapCanvas& canvas, SeededRandom& random, const cv::Rect& poster,
                         const cv::Scalar& ink, int size) {
  const int k1 = scaled(1, size);
  // A picture block in the upper part: rectangles or stripes.
  const cv::Rect picture(poster.x + 3 * k1, poster.y + 3 * k1, poster.width - 6 * k1,
                         poster.height / 2);
  if (random.chance(0.5)) {
    for (int i = random.uniformInt(2, 4); i > 0; --i) {
      const int w = random.uniformInt(picture.width / 4, picture.width / 2 + 1);
      const int h = random.uniformInt(picture.height / 4, picture.height / 2 + 1);
      canvas.rect({picture.x + random.uniformInt(0, picture.width - w),
                   picture.y + random.uniformInt(0, picture.height - h), w, h},
                  random.vividColour());
    }
  } else {
    const int band = random.uniformInt(3, 7) * k1;
    const cv::Scalar a = random.vividColour(), b = random.vividColour();
    for (int y = picture.y, i = 0; y < picture.y + picture.height; y += band, ++i)
      canvas.rect({picture.x, y, picture.width, std::min(band, picture.y + picture.height - y)},
                  i % 2 ? a : b);
    canvas.circle({picture.x + random.uniformInt(0, picture.width), picture.y + picture.height / 2},
                  random.uniformInt(4, 9) * k1, random.vividColour());
  }
  // Text-like lines below it.
  const double scale = random.uniform(0.28, 0.42) * size / 256.0;
  int baseline = picture.y + picture.height + 10 * k1;
  while (baseline < poster.y + poster.height - 3 * k1) {
    canvas.text(randomWord(random, 3, 7), {poster.x + 3 * k1, baseline}, scale, ink, 1);
    baseline += random.uniformInt(9, 13) * k1;
  }
}

}  // namespace

cv::Mat paintBricks(SeededRandom& random, int size) {
  const cv::Scalar mortar = random.jitter({165, 172, 178}, 15);
  WrapCanvas canvas(size, mortar);
  const cv::Scalar base = random.jitter(
      random.pick({{60, 80, 160}, {70, 100, 175}, {95, 125, 150}, {120, 170, 205}, {80, 85, 125}}),
      15);
  const int row_counts[] = {8, 10, 12};
  const int rows = row_counts[random.uniformInt(0, 2)];
  const int bricks_per_row = std::max(2, rows * 2 / 5);
  const int gap = scaled(3, size);
  for (int row = 0; row < rows; ++row) {
    const int y0 = row * size / rows, y1 = (row + 1) * size / rows;
    const int offset = (row % 2) * size / (2 * bricks_per_row) + random.uniformInt(-2, 2);
    for (int i = 0; i < bricks_per_row; ++i) {
      const int x0 = offset + i * size / bricks_per_row;
      const int x1 = offset + (i + 1) * size / bricks_per_row;
      const cv::Rect brick(x0 + gap / 2, y0 + gap / 2, x1 - x0 - gap, y1 - y0 - gap);
      const cv::Scalar colour = random.shade(random.jitter(base, 10), 0.2);
      canvas.rect(brick, colour);
      // Pits and lighter grains on the face; a chipped corner now and then.
      for (int spot = random.uniformInt(2, 5); spot > 0; --spot)
        canvas.circle({brick.x + random.uniformInt(2, brick.width - 3),
                       brick.y + random.uniformInt(2, brick.height - 3)},
                      random.uniformInt(1, scaled(2, size)), random.shade(colour, 0.35));
      if (random.chance(0.3)) {
        const int chip = random.uniformInt(2, scaled(5, size));
        canvas.rect({random.chance(0.5) ? brick.x : brick.x + brick.width - chip,
                     random.chance(0.5) ? brick.y : brick.y + brick.height - chip, chip, chip},
                    mortar);
      }
    }
  }
  return canvas.finish(random, 5, 0.7);
}

cv::Mat paintPosters(SeededRandom& random, int size) {
  WrapCanvas canvas(size, random.jitter({200, 205, 210}, 25));
  const int grid = 3;
  const int cell = size / grid;
  for (int gy = 0; gy < grid; ++gy)
    for (int gx = 0; gx < grid; ++gx) {
      const int w = static_cast<int>(cell * random.uniform(0.7, 0.92));
      const int h = static_cast<int>(cell * random.uniform(0.7, 0.92));
      const cv::Rect poster(gx * cell + random.uniformInt(0, cell - w),
                            gy * cell + random.uniformInt(0, cell - h), w, h);
      const bool light_paper = random.chance(0.6);
      const cv::Scalar paper =
          light_paper ? random.jitter({225, 230, 235}, 20) : random.vividColour();
      const cv::Scalar ink =
          light_paper ? random.jitter({30, 30, 30}, 25) : random.jitter({240, 240, 240}, 10);
      canvas.rect(poster, paper);
      canvas.rect(poster, random.jitter({50, 50, 50}, 30), scaled(1, size));
      paintPosterContents(canvas, random, poster, ink, size);
      // Pins in the corners.
      canvas.circle({poster.x + 2, poster.y + 2}, scaled(1.5, size), random.vividColour());
      canvas.circle({poster.x + w - 3, poster.y + 2}, scaled(1.5, size), random.vividColour());
    }
  return canvas.finish(random, 3, 0.6);
}

cv::Mat paintChecker(SeededRandom& random, int size) {
  const int squares = 8;
  const int side = size / squares;
  const cv::Scalar dark = random.jitter({45, 45, 50}, 30);
  const cv::Scalar light = random.jitter({215, 215, 210}, 30);
  WrapCanvas canvas(size, dark);
  for (int j = 0; j < squares; ++j)
    for (int i = 0; i < squares; ++i) {
      const bool is_light = (i + j) % 2 == 0;
      const cv::Rect square(i * side, j * side, side, side);
      // Each square a slightly different shade, some with a mark: a perfect checker is
      // ambiguous for KLT; these break the periodicity the way real patterns do.
      canvas.rect(square, random.shade(is_light ? light : dark, 0.12));
      if (random.chance(0.35)) {
        const int mark = random.uniformInt(side / 5, side / 3);
        const cv::Point centre(square.x + random.uniformInt(mark, side - mark),
                               square.y + random.uniformInt(mark, side - mark));
        const cv::Scalar ink = random.shade(is_light ? dark : light, 0.1);
        if (random.chance(0.5))
          canvas.circle(centre, mark / 2 + 1, ink);
        else
          canvas.rect({centre.x - mark / 2, centre.y - mark / 2, mark, mark}, ink);
      }
    }
  return canvas.finish(random, 3, 0.6);
}

cv::Mat paintTiles(SeededRandom& random, int size) {
  const int per_side = random.chance(0.5) ? 4 : 8;
  const int side = size / per_side;
  const int grout = scaled(per_side == 4 ? 3 : 2, size);
  WrapCanvas canvas(size, random.jitter({95, 100, 105}, 20));
  const cv::Scalar base = random.jitter(
      random.pick({{175, 195, 210}, {160, 160, 160}, {80, 110, 170}, {170, 150, 120}}), 15);
  for (int j = 0; j < per_side; ++j)
    for (int i = 0; i < per_side; ++i) {
      const cv::Rect tile(i * side + grout / 2, j * side + grout / 2, side - grout, side - grout);
      const cv::Scalar colour = random.shade(random.jitter(base, 8), 0.1);
      canvas.rect(tile, colour);
      // Terrazzo flecks: small dark and light chips all over the tile.
      const int flecks = side * side / 200;
      for (int f = 0; f < flecks; ++f)
        canvas.circle({tile.x + random.uniformInt(1, tile.width - 2),
                       tile.y + random.uniformInt(1, tile.height - 2)},
                      random.uniformInt(1, scaled(2, size)), random.shade(colour, 0.45));
      if (random.chance(0.15)) {  // a hairline crack
        const cv::Point a(tile.x + random.uniformInt(0, tile.width), tile.y);
        const cv::Point b(tile.x + random.uniformInt(0, tile.width), tile.y + tile.height);
        canvas.line(a, b, random.shade(colour, 0.1) * 0.6, 1);
      }
    }
  return canvas.finish(random, 4, 0.7);
}

cv::Mat paintAsphalt(SeededRandom& random, int size) {
  const cv::Scalar base = random.jitter({72, 72, 74}, 10);
  WrapCanvas canvas(size, base);
  // Repairs: darker and lighter patches with straight edges.
  for (int i = random.uniformInt(1, 3); i > 0; --i) {
    const cv::Point corner = randomPoint(random, size);
    canvas.rect({corner.x, corner.y, random.uniformInt(size / 8, size / 3),
                 random.uniformInt(size / 8, size / 3)},
                random.shade(base, 0.25));
  }
  // Aggregate: dense speckle of stones from dark to light grey.
  for (int i = size * size / 45; i > 0; --i) {
    const int grey = random.uniformInt(25, 160);
    canvas.circle(randomPoint(random, size), random.chance(0.8) ? 1 : scaled(2, size),
                  cv::Scalar(grey, grey, grey + random.uniformInt(0, 6)));
  }
  // Cracks: random walks.
  for (int i = random.uniformInt(2, 4); i > 0; --i) {
    std::vector<cv::Point> crack{randomPoint(random, size)};
    for (int s = random.uniformInt(4, 9); s > 0; --s)
      crack.push_back(crack.back() + cv::Point(random.uniformInt(-12, 12) * size / 256,
                                               random.uniformInt(-12, 12) * size / 256));
    canvas.polyline(crack, {30, 30, 32}, 1);
  }
  // A dashed lane mark along v (two dashes per tile) in white or yellow paint.
  const cv::Scalar paint =
      random.chance(0.7) ? random.jitter({225, 228, 230}, 12) : random.jitter({40, 200, 235}, 12);
  const int lane_x = random.uniformInt(0, size - 1), lane_width = scaled(8, size);
  for (int dash = 0; dash < 2; ++dash)
    canvas.rect({lane_x, dash * size / 2 + random.uniformInt(0, 4), lane_width, size / 4}, paint);
  // Worn paint: stones show through the mark.
  for (int i = size / 4; i > 0; --i)
    canvas.circle({lane_x + random.uniformInt(0, lane_width), random.uniformInt(0, size - 1)}, 1,
                  random.shade(base, 0.4));
  return canvas.finish(random, 6, 0.7);
}

cv::Mat paintWood(SeededRandom& random, int size) {
  const int planks = random.chance(0.5) ? 4 : 8;
  const int height = size / planks;
  const cv::Scalar base = random.jitter(
      random.pick({{60, 110, 160}, {45, 85, 130}, {95, 145, 190}, {40, 70, 110}}), 10);
  const cv::Scalar seam = base * 0.35;
  WrapCanvas canvas(size, seam);
  for (int p = 0; p < planks; ++p) {
    const int y0 = p * height;
    const cv::Scalar colour = random.shade(random.jitter(base, 8), 0.15);
    canvas.rect({0, y0 + 1, size, height - 1}, colour);
    // Grain: periodic wavy lines (integer frequencies keep them seamless across the wrap).
    for (int g = random.uniformInt(5, 9); g > 0; --g) {
      const double y_mid = y0 + random.uniform(2, height - 2);
      const double amplitude = random.uniform(0.5, 3.0) * size / 256.0;
      const int frequency = random.uniformInt(1, 3);
      const double phase = random.uniform(0, 2 * M_PI);
      std::vector<cv::Point> grain;
      for (int x = 0; x <= size; x += 4)
        grain.emplace_back(
            x, static_cast<int>(std::lround(
                   y_mid + amplitude * std::sin(2 * M_PI * frequency * x / size + phase))));
      canvas.polyline(grain, random.shade(colour, 0.08) * 0.8, 1);
    }
    // Knots with rings.
    for (int knot = random.uniformInt(0, 2); knot > 0; --knot) {
      const cv::Point centre(random.uniformInt(0, size - 1),
                             y0 + random.uniformInt(height / 4, 3 * height / 4));
      const cv::Size axes(random.uniformInt(4, 9) * size / 256 + 1,
                          random.uniformInt(2, 4) * size / 256 + 1);
      canvas.ellipse(centre, axes, 0, colour * 0.55);
      canvas.ellipse(centre, axes * 2, 0, colour * 0.75, 1);
    }
    // Plank ends: butt joints with two nails each side.
    const int joints = random.uniformInt(1, 2);
    for (int j = 0; j < joints; ++j) {
      const int x = random.uniformInt(0, size - 1);
      canvas.line({x, y0}, {x, y0 + height}, seam, scaled(1.5, size));
      for (int side = -1; side <= 1; side += 2)
        for (int n = 1; n <= 2; ++n)
          canvas.circle({x + side * scaled(5, size), y0 + n * height / 3}, scaled(1.2, size),
                        {40, 40, 45});
    }
  }
  return canvas.finish(random, 4, 0.6);
}

}  // namespace dynslam::sim::detail
