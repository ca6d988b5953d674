#pragma once
// One fixed, well-spread colour per id (track, instance label), so the same object has the same
// colour in every picture: annotated frames, contact sheets, maps.
#include <opencv2/core/types.hpp>

namespace dynslam::viz {

/// BGR colour of `id`; id 0 (static scene, no object) is black. Channels stay in [64, 255] so
/// every object shows on a dark background.
cv::Scalar colourForId(int id);

}  // namespace dynslam::viz
