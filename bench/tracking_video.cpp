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

}  // namespace

void benchVideo(const VideoBenchSettings& s) {
  cv::VideoCapture capture(s.video);
  if (!capture.isOpened()) throw std::runtime_error("cannot open the video '" + s.video + "'");
  const double fps = capture.get(cv::CAP_PROP_FPS) > 0 ? capture.get(cv::CAP_PROP_FPS) : 25.0;
  const int total = int(capture.get(cv::CAP_PROP_FRAME_COUNT));
  const int frames = s.frames ? std::min<int>(int(s.frames), total) : total;
  detection::OnnxYoloDetectorSettings ds;
  ds.model = s.model;
  detection::OnnxYoloDetector detector(ds, detection::ClassMap());
  tracking::KalmanBoxTracker tracker(s.tracker);

  const int stripFrames = 4;
  std::vector<int> stripAt;
  for (int k = 0; k < stripFrames; ++k) stripAt.push_back((2 * k + 1) * frames / (2 * stripFrames));
  std::vector<cv::Mat> strip;
  std::map<int, TrackLife> lives;
  std::vector<double> detectMs, trackMs;
  size_t detections = 0;
  cv::Mat bgr;
  cv::Size image;
  for (int i = 0; i < frames && capture.read(bgr); ++i) {
    image = bgr.size();
    auto t0 = std::chrono::steady_clock::now();
    const auto dets = detector.detectImage(bgr);
    auto t1 = std::chrono::steady_clock::now();
    std::vector<tracking::BoxObservation> obs;
    const bool appearance = tracker.params().reid_max_distance > 0;
    for (const auto& d : dets)
      obs.push_back({d.box, 0.0, d.category, d.model,
                     appearance ? tracking::bodyHistogram(bgr, d.box) : cv::Mat()});
    tracker.predict(i / fps);
    tracker.update(obs, bgr.size());
    const auto tracks = tracker.tracks();
    auto t2 = std::chrono::steady_clock::now();
    detectMs.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    trackMs.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    detections += dets.size();
    for (const auto& t : tracks) {
      if (t.state != core::TrackState::Confirmed || t.detection < 0) continue;
      TrackLife& life = lives[t.id];
      if (life.first < 0) life.first = i, life.first_box = t.box;
      life.last = i, life.last_box = t.box;
      ++life.matched;
    }
    if (std::find(stripAt.begin(), stripAt.end(), i) != stripAt.end()) {
      core::Frame frame;  // what the pipeline's renderer draws: image, detections, tracks
      frame.index = i;
      frame.t = i / fps;
      frame.rgb = bgr;
      frame.detections = dets;
      frame.detections_fresh = true;
      frame.tracks = tracks;
      cv::Mat small;
      cv::resize(viz::renderAnnotatedFrame(frame), small, cv::Size(), 0.6, 0.6, cv::INTER_AREA);
      strip.push_back(small);
    }
  }

  // Identity breaks visible without ground truth: a track that starts where another one
  // ended shortly before (its last box and the new first box overlap, within 2 s) is most
  // likely the same person under a new ID (a fragmentation, or a switch after a crossing).
  // Starts at the image border are people walking in and are not counted.
  size_t breaks = 0, borderStarts = 0;
  double length = 0;
  for (const auto& [id, life] : lives) {
    length += life.last - life.first + 1;
    const cv::Rect2f b = life.first_box;
    if (b.x < 8 || b.y < 8 || b.x + b.width > image.width - 8 || b.y + b.height > image.height - 8)
      ++borderStarts;
    for (const auto& [other, before] : lives)
      if (other != id && before.last < life.first && life.first - before.last <= 2 * fps &&
          (before.last_box & life.first_box).area() > 0.3 * life.first_box.area()) {
        ++breaks;
        break;
      }
  }
  std::printf("video           %s, %d frames %dx%d at %.1f Hz\n", s.video.c_str(), frames,
              image.width, image.height, fps);
  std::printf("detector        YOLOX-nano (%s), %.2f detections per frame, median %.1f ms\n",
              s.model.c_str(), frames ? double(detections) / frames : 0.0,
              dynslam::core::upperMedian(detectMs));
  std::printf(
      "tracker         rho_min %.2f (no depth: plain IoU), max_age %d, min_hits %d; "
      "median %.4f ms per frame\n",
      s.tracker.rho_min, s.tracker.max_age, s.tracker.min_hits,
      dynslam::core::upperMedian(trackMs));
  std::printf(
      "tracks          %zu confirmed, mean length %.1f frames (%.1f s), %zu started "
      "at the image border\n",
      lives.size(), lives.empty() ? 0.0 : length / lives.size(),
      lives.empty() ? 0.0 : length / lives.size() / fps, borderStarts);
  std::printf(
      "identity breaks %zu (a new track starting on the last box of one that ended "
      "< 2 s before)\n",
      breaks);
  if (!strip.empty()) {
    cv::Mat row;
    cv::hconcat(strip, row);
    if (!cv::imwrite(s.strip, row)) throw std::runtime_error("cannot write '" + s.strip + "'");
    std::printf("strip           %s (frames", s.strip.c_str());
    for (int f : stripAt) std::printf(" %d", f);
    std::printf("; grey: detections, coloured: tracks)\n");
  }
}
