#pragma once
// The tracker on a real video (no ground truth): YOLOX-nano detections, plain IoU (the video has
// no depth). Prints the number of tracks, their mean length and the identity breaks it can see,
// and writes an annotated strip of frames.
#include <dynslam/tracking/KalmanBoxTracker.h>

#include <string>

struct VideoBenchSettings {
  std::string video, model, strip;
  size_t frames = 0;  // 0: all
  dynslam::tracking::KalmanBoxTrackerParams tracker;
};

void benchVideo(const VideoBenchSettings& settings);
