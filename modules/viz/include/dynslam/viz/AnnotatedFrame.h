#pragma once
// The picture of one frame after the perception stages: what a person checks first when the
// detector, segmenter or tracker misbehaves. Drawn on a copy of the colour image:
//   - each object mask tinted with its track's colour (the detection's own colour when it has
//     no track), so leaks into the background and holes show at a glance;
//   - detector boxes thin and grey, with class and score;
//   - track boxes in the track's colour, labelled "#id class d=2.31m" ("no depth" without one);
//     while the track predicts without a detection, a thin box labelled "#id ~" only;
//   - tracked features as small dots coloured by their class (FeatureClass): static green,
//     rigid orange, non-rigid magenta, so a person's features classified static stand out;
//   - a header with the frame index, time and counts.
#include <dynslam/core/Frame.h>

#include <opencv2/core/mat.hpp>

namespace dynslam::viz {

struct AnnotationOptions {
  double mask_alpha = 0.45;  ///< tint strength of the masks (0: masks not drawn)
  bool detections = true;    ///< draw the detector's boxes
  bool tracks = true;        ///< draw the tracks
  bool features = true;      ///< draw the tracked features, coloured by class
  double font_scale = 0.45;
};

/// Returns the annotated image (CV_8UC3, the frame's size). A frame without colour is drawn on
/// its depth, grey-scaled; a frame with neither gives a black 640x480 image with the header.
cv::Mat renderAnnotatedFrame(const core::Frame& frame, const AnnotationOptions& options = {});

/// BGR colour of a feature class in the annotated frame.
cv::Scalar featureClassColour(core::FeatureClass feature_class);

}  // namespace dynslam::viz
