// Textures of the moving things: car paint (panels, seams, windows, lights, plate), clothing
// (plaid, dots, prints, checks with seams and buttons) and skin. Cars and clothes are where
// the dynamic-object features come from, so they get as many corners as the walls; skin is
// smooth with freckles, as it is.
#include "TexturePainters.h"

#include <cmath>
#include <string>

namespace dynslam::sim::detail {
namespace {

int scaled(double pixels_at_256, int size) {
  return std::max(1, static_cast<int>(std::lround(pixels_at_256 * size / 256.0)));
}

// Dashed stitching along a straight seam.
void stitches(WrapCanvas& canvas, cv::Point from, cv::Point to, const cv::Scalar& thread,
              int size) {
  const cv::Point2d step = cv::Point2d(to - from) / std::max(1.0, cv::norm(to - from));
  const double dash = scaled(3, size);
  for (double t = 0; t + dash <= cv::norm(to - from); t += 2 * dash) {
    const cv::Point a = from + cv::Point(step * t), b = from + cv::Point(step * (t + dash));
    canvas.line(a, b, thread, 1);
  }
}

void paintPlaid(WrapCanvas& canvas, SeededRandom& random, int size) {
  for (int axis = 0; axis < 2; ++axis)
    for (int i = random.uniformInt(5, 8); i > 0; --i) {
      const int at = random.uniformInt(0, size - 1), width = random.uniformInt(2, size / 14);
      const cv::Rect band = axis == 0 ? cv::Rect(at, 0, width, size) : cv::Rect(0, at, size, width);
      canvas.blendRect(band, random.vividColour(), random.uniform(0.35, 0.6));
    }
}

void paintDots(WrapCanvas& canvas, SeededRandom& random, int size, const cv::Scalar& fabric) {
  const int pitch = random.uniformInt(14, 22) * size / 256;
  const cv::Scalar ink = random.chance(0.5) ? cv::Scalar(235, 235, 235) : random.vividColour();
  for (int y = 0; y < size; y += pitch)
    for (int x = (y / pitch % 2) * pitch / 2; x < size; x += pitch) {
      if (random.chance(0.2))
        canvas.rect({x - 2, y - 2, 5, 5}, random.shade(fabric, 0.5));
      else
        canvas.circle({x, y}, random.uniformInt(2, pitch / 4 + 2), ink);
    }
}

void paintPrint(WrapCanvas& canvas, SeededRandom& random, int size) {
  for (int i = random.uniformInt(30, 45); i > 0; --i) {
    const cv::Point at(random.uniformInt(0, size - 1), random.uniformInt(0, size - 1));
    const int extent = random.uniformInt(4, 14) * size / 256 + 2;
    switch (random.uniformInt(0, 2)) {
      case 0:
        canvas.rect({at.x, at.y, extent, random.uniformInt(3, extent)}, random.vividColour());
        break;
      case 1:
        canvas.circle(at, extent / 2 + 1, random.vividColour());
        break;
      default:
        canvas.text(random.chance(0.5) ? "XL" : "23", at, 0.4 * size / 256.0, random.vividColour(),
                    1);
    }
  }
}

void paintChecks(WrapCanvas& canvas, SeededRandom& random, int size, const cv::Scalar& fabric) {
  const int side = size / 16;
  const cv::Scalar ink = random.shade(fabric, 0.6) * 0.5;
  for (int j = 0; j < 16; ++j)
    for (int i = (j % 2); i < 16; i += 2) canvas.rect({i * side, j * side, side, side}, ink);
  for (int d = 0; d < 16; d += 2)
    canvas.line({d * side, 0}, {d * side + size, size}, random.shade(fabric, 0.3), 1);
}

}  // namespace

cv::Mat paintCarPaint(SeededRandom& random, int size) {
  const cv::Scalar paint = random.jitter(random.pick({{40, 40, 190},
                                                      {160, 70, 30},
                                                      {230, 230, 230},
                                                      {35, 35, 35},
                                                      {180, 180, 175},
                                                      {60, 120, 50},
                                                      {40, 200, 230}}),
                                         10);
  WrapCanvas canvas(size, paint);
  const cv::Scalar seam = paint * 0.35 + cv::Scalar(10, 10, 10);
  const int k1 = scaled(1, size);
  // Windows in the upper part: dark glass in rubber seals, split by pillars, with reflections.
  const int window_top = size / 12, window_bottom = 2 * size / 5;
  const int windows = random.uniformInt(2, 3);
  for (int i = 0; i < windows; ++i) {
    const int x0 = i * size / windows + 4 * k1, x1 = (i + 1) * size / windows - 4 * k1;
    const cv::Rect glass(x0, window_top, x1 - x0, window_bottom - window_top);
    canvas.rect(glass, random.jitter({60, 45, 40}, 12));
    canvas.rect(glass, {25, 25, 25}, 2 * k1);
    const int reflection_x = x0 + random.uniformInt(2 * k1, glass.width - glass.height / 2);
    canvas.line({reflection_x, window_bottom - 2 * k1},
                {reflection_x + glass.height / 2, window_top + 2 * k1}, {120, 110, 105}, 3 * k1);
  }
  // Panel seams: the belt line, the door gaps below it, a character line.
  const int belt = window_bottom + 6 * k1;
  canvas.line({0, belt}, {size, belt}, seam, k1);
  canvas.line({0, belt + size / 6}, {size, belt + size / 6}, random.shade(paint, 0.15) * 1.15, k1);
  for (int i = 0; i < windows; ++i) {
    const int x = i * size / windows + random.uniformInt(-3, 3);
    canvas.line({x, belt}, {x, size - size / 10}, seam, k1);
    // Door handle right of the gap.
    canvas.rect({x + 10 * k1, belt + 8 * k1, 14 * k1, 4 * k1}, seam);
  }
  // Sill, lights, plate with characters, a badge.
  canvas.rect({0, size - size / 10, size, size / 10}, paint * 0.5);
  canvas.rect({random.uniformInt(0, size / 2), belt + size / 4, 16 * k1, 8 * k1},
              random.chance(0.5) ? cv::Scalar(30, 120, 245) : cv::Scalar(40, 40, 210));
  const cv::Rect plate(size / 2 + random.uniformInt(0, size / 4), belt + size / 4, 40 * k1,
                       12 * k1);
  canvas.rect(plate, {235, 235, 235});
  canvas.rect(plate, {20, 20, 20}, 1);
  canvas.text("DS" + std::to_string(random.uniformInt(10, 99)),
              {plate.x + 3 * k1, plate.y + 9 * k1}, 0.3 * size / 256.0, {20, 20, 20}, 1);
  canvas.ellipse({random.uniformInt(0, size - 1), belt + size / 8}, {5 * k1, 3 * k1}, 0,
                 {200, 200, 205});
  // Road dirt on the lower panels.
  for (int i = size / 2; i > 0; --i)
    canvas.circle({random.uniformInt(0, size - 1), random.uniformInt(belt + size / 5, size - 1)}, 1,
                  random.shade(paint * 0.6, 0.3));
  return canvas.finish(random, 2, 0.6);
}

cv::Mat paintClothing(SeededRandom& random, int size) {
  const cv::Scalar fabric = random.jitter(random.pick({{120, 60, 30},
                                                       {40, 40, 40},
                                                       {200, 200, 200},
                                                       {50, 50, 150},
                                                       {60, 110, 60},
                                                       {110, 150, 190},
                                                       {140, 100, 120}}),
                                          15);
  WrapCanvas canvas(size, fabric);
  switch (random.uniformInt(0, 3)) {
    case 0:
      paintPlaid(canvas, random, size);
      break;
    case 1:
      paintDots(canvas, random, size, fabric);
      break;
    case 2:
      paintPrint(canvas, random, size);
      break;
    default:
      paintChecks(canvas, random, size, fabric);
  }
  // Seams with stitching, a pocket and buttons: corners on any pattern.
  const cv::Scalar thread = random.shade(fabric, 0.5) * 0.6 + cv::Scalar(40, 40, 40);
  for (int i = 0; i < 2; ++i) {
    const int x = random.uniformInt(0, size - 1), y = random.uniformInt(0, size - 1);
    canvas.line({x, 0}, {x, size}, fabric * 0.5, 1);
    stitches(canvas, {x + 3, 0}, {x + 3, size}, thread, size);
    canvas.line({0, y}, {size, y}, fabric * 0.5, 1);
    stitches(canvas, {0, y + 3}, {size, y + 3}, thread, size);
  }
  const int pocket = size / 5;
  const cv::Point pocket_at(random.uniformInt(0, size - 1), random.uniformInt(0, size - 1));
  canvas.rect({pocket_at.x, pocket_at.y, pocket, pocket}, fabric * 0.55, 1);
  stitches(canvas, pocket_at + cv::Point(2, 2), pocket_at + cv::Point(pocket - 2, 2), thread, size);
  for (int b = 0; b < 4; ++b) {
    const cv::Point button(pocket_at.x - 12 * size / 256, pocket_at.y + b * size / 8);
    canvas.circle(button, scaled(3, size), {200, 200, 190});
    canvas.circle(button, 1, {40, 40, 40});
  }
  return canvas.finish(random, 6, 0.7);
}

cv::Mat paintSkin(SeededRandom& random, int size) {
  const cv::Scalar tone = random.jitter(random.pick({{170, 190, 235},
                                                     {140, 170, 220},
                                                     {110, 140, 190},
                                                     {80, 105, 150},
                                                     {50, 70, 110},
                                                     {60, 90, 140}}),
                                        6);
  WrapCanvas canvas(size, tone);
  // Low-contrast mottling, then freckles and pores, and a few moles.
  for (int i = 24; i > 0; --i)
    canvas.ellipse(
        {random.uniformInt(0, size - 1), random.uniformInt(0, size - 1)},
        {random.uniformInt(8, 30) * size / 256 + 1, random.uniformInt(8, 30) * size / 256 + 1},
        random.uniform(0, 180), random.shade(tone, 0.05));
  for (int i = size * size / 1500; i > 0; --i)
    canvas.circle({random.uniformInt(0, size - 1), random.uniformInt(0, size - 1)}, 1,
                  random.shade(tone * 0.88, 0.04));
  for (int i = random.uniformInt(2, 5); i > 0; --i)
    canvas.circle({random.uniformInt(0, size - 1), random.uniformInt(0, size - 1)}, scaled(2, size),
                  tone * 0.5);
  return canvas.finish(random, 3, 0.8);
}

}  // namespace dynslam::sim::detail
