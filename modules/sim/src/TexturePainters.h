#pragma once
// One generator per TextureKind (internal to the sim module). Each paints a seamless square of
// `size` pixels from `random` and returns the finished CV_8UC3 image.
#include "TextureCanvas.h"

namespace dynslam::sim::detail {

cv::Mat paintBricks(SeededRandom& random, int size);
cv::Mat paintPosters(SeededRandom& random, int size);
cv::Mat paintChecker(SeededRandom& random, int size);
cv::Mat paintTiles(SeededRandom& random, int size);
cv::Mat paintAsphalt(SeededRandom& random, int size);
cv::Mat paintCarPaint(SeededRandom& random, int size);
cv::Mat paintClothing(SeededRandom& random, int size);
cv::Mat paintSkin(SeededRandom& random, int size);
cv::Mat paintWood(SeededRandom& random, int size);

}  // namespace dynslam::sim::detail
