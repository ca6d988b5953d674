#include "tracking_video.h"

#include <dynslam/core/Median.h>
#include <dynslam/detection/OnnxYoloDetector.h>
#include <dynslam/tracking/Appearance.h>
#include <dynslam/viz/AnnotatedFrame.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace {

using namespace dynslam;

/// What the bench remembers of one track.
struct TrackLife {
  int first = -1, last = -1;  // frames of the first and last match while confirmed
  int matched = 0;            // frames matched while confirmed
  cv::Rect2f first_box, last_box;
};

/// What one pass over the video gathered.
struct VideoRun {
  double fps = 25.0;
  int frames = 0;
  cv::Size image;
  std::map<int, TrackLife> lives;
  std::vector<double> detectMs, trackMs;
  size_t detections = 0;
  std::vector<int> stripAt;  // the frames drawn into the strip
  std::vector<cv::Mat> strip;
};

/// Frame i as the pipeline's renderer draws it (image, detections, tracks), at 60 %.
cv::Mat stripFrame(int i, double fps, const cv::Mat& bgr, const std::vector<core::Detection>& dets,
                   const std::vector<core::Track>& tracks) {
  core::Frame frame;
  frame.index = i;
  frame.t = i / fps;
  frame.rgb = bgr;
  frame.detections = dets;
  frame.detections_fresh = true;
  frame.tracks = tracks;
  cv::Mat small;
  cv::resize(viz::renderAnnotatedFrame(frame), small, cv::Size(), 0.6, 0.6, cv::INTER_AREA);
  return small;
}

/// Detects and tracks every frame (up to s.frames), timing both, and keeps each confirmed
/// track's life and the strip's frames.
VideoRun trackVideo(const VideoBenchSettings& s) {
  cv::VideoCapture capture(s.video);
  if (!capture.isOpened()) throw std::runtime_error("cannot open the video '" + s.video + "'");
  VideoRun r;
  r.fps = capture.get(cv::CAP_PROP_FPS) > 0 ? capture.get(cv::CAP_PROP_FPS) : 25.0;
  const int total = int(capture.get(cv::CAP_PROP_FRAME_COUNT));
  r.frames = s.frames ? std::min<int>(int(s.frames), total) : total;
  detection::OnnxYoloDetectorSettings ds;
  ds.model = s.model;
  detection::OnnxYoloDetector detector(ds, detection::ClassMap());
  tracking::KalmanBoxTracker tracker(s.tracker);
  const int stripFrames = 4;
  for (int k = 0; k < stripFrames; ++k)
    r.stripAt.push_back((2 * k + 1) * r.frames / (2 * stripFrames));
  cv::Mat bgr;
  for (int i = 0; i < r.frames && capture.read(bgr); ++i) {
    r.image = bgr.size();
    auto t0 = std::chrono::steady_clock::now();
    const auto dets = detector.detectImage(bgr);
    auto t1 = std::chrono::steady_clock::now();
    std::vector<tracking::BoxObservation> obs;
    const bool appearance = tracker.params().reid_max_distance > 0;
    for (const auto& d : dets)
      obs.push_back({d.box, 0.0, d.category, d.model,
                     appearance ? tracking::bodyHistogram(bgr, d.box) : cv::Mat()});
    tracker.predict(i / r.fps);
    tracker.update(obs, bgr.size());
    const auto tracks = tracker.tracks();
    auto t2 = std::chrono::steady_clock::now();
    r.detectMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    r.trackMs.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    r.detections += dets.size();
    for (const auto& t : tracks) {
      if (t.state != core::TrackState::Confirmed || t.detection < 0) continue;
      TrackLife& life = r.lives[t.id];
      if (life.first < 0) life.first = i, life.first_box = t.box;
      life.last = i, life.last_box = t.box;
      ++life.matched;
    }
    if (std::find(r.stripAt.begin(), r.stripAt.end(), i) != r.stripAt.end())
      r.strip.push_back(stripFrame(i, r.fps, bgr, dets, tracks));
  }
  return r;
}

/// Identity breaks visible without ground truth: a track that starts where another one ended
/// shortly before (its last box and the new first box overlap, within 2 s) is most likely the
/// same person under a new ID (a fragmentation, or a switch after a crossing). Starts at the
/// image border are people walking in and are not counted but tallied (`borderStarts`);
/// `length`: the confirmed tracks' frames, summed.
size_t identityBreaks(const VideoRun& r, size_t& borderStarts, double& length) {
  size_t breaks = 0;
  borderStarts = 0;
  length = 0;
  for (const auto& [id, life] : r.lives) {
    length += life.last - life.first + 1;
    const cv::Rect2f b = life.first_box;
    if (b.x < 8 || b.y < 8 || b.x + b.width > r.image.width - 8 ||
        b.y + b.height > r.image.height - 8)
      ++borderStarts;
    for (const auto& [other, before] : r.lives)
      if (other != id && before.last < life.first && life.first - before.last <= 2 * r.fps &&
          (before.last_box & life.first_box).area() > 0.3 * life.first_box.area()) {
        ++breaks;
        break;
      }
  }
  return breaks;
}

}  // namespace

void benchVideo(const VideoBenchSettings& s) {
  const VideoRun r = trackVideo(s);
  size_t borderStarts = 0;
  double length = 0;
  const size_t breaks = identityBreaks(r, borderStarts, length);
  const auto& lives = r.lives;
  std::printf("video           %s, %d frames %dx%d at %.1f Hz\n", s.video.c_str(), r.frames,
              r.image.width, r.image.height, r.fps);
  std::printf("detector        YOLOX-nano (%s), %.2f detections per frame, median %.1f ms\n",
              s.model.c_str(), r.frames ? double(r.detections) / r.frames : 0.0,
              dynslam::core::upperMedian(r.detectMs));
  std::printf(
      "tracker         rho_min %.2f (no depth: plain IoU), max_age %d, min_hits %d; "
      "median %.4f ms per frame\n",
      s.tracker.rho_min, s.tracker.max_age, s.tracker.min_hits,
      dynslam::core::upperMedian(r.trackMs));
  std::printf(
      "tracks          %zu confirmed, mean length %.1f frames (%.1f s), %zu started "
      "at the image border\n",
      lives.size(), lives.empty() ? 0.0 : length / lives.size(),
      lives.empty() ? 0.0 : length / lives.size() / r.fps, borderStarts);
  std::printf(
      "identity breaks %zu (a new track starting on the last box of one that ended "
      "< 2 s before)\n",
      breaks);
  if (!r.strip.empty()) {
    cv::Mat row;
    cv::hconcat(r.strip, row);
    if (!cv::imwrite(s.strip, row)) throw std::runtime_error("cannot write '" + s.strip + "'");
    std::printf("strip           %s (frames", s.strip.c_str());
    for (int f : r.stripAt) std::printf(" %d", f);
    std::printf("; grey: detections, coloured: tracks)\n");
  }
}
