#pragma once
// Cuts walking people out of a static camera's video into a SpriteBank: each frame's foreground
// blobs (VideoForeground.h) are followed over frames by box overlap, each followed person's
// frames split where a frame cannot be used, and each unbroken stretch kept when it covers at
// least one gait cycle. A frame cannot be used when the person is cut by the image border, when
// the blob holds two people (two followed people share it, or it is far wider or taller than
// the person is), or when it is shorter than the minimum height. Deterministic: the same frames
// give the same bank, byte for byte.
#include <dynslam/sim/SpriteBank.h>
#include <dynslam/sim/VideoForeground.h>

#include <memory>
#include <string>

namespace dynslam::sim {

struct SpriteExtractionOptions {
  int min_height_px = 80;        ///< people shorter than this in a frame are not kept there
  int border_margin_px = 3;      ///< a blob this close to the image edge is cut by it
  /// The walked distance of one gait cycle (two steps) in body heights: a stride is about
  /// 0.4 heights.
  double gait_cycle_heights = 0.8;
  double min_gait_cycles = 1;    ///< stretches that walk less are too short to loop
  /// One walking person's box is at most about half as wide as tall over a stretch (median
  /// 0.31-0.46 in vtest.avi, arms and strides included); a pair side by side is wider.
  double max_median_width = 0.55;
  int max_missed_frames = 3;     ///< a person not seen for longer is ended
  ForegroundOptions foreground;
};

/// What the extractor saw and why it left frames out.
struct SpriteExtractionReport {
  size_t frames = 0;            ///< video frames read
  size_t followed = 0;          ///< people followed (blobs linked over frames)
  size_t people = 0;            ///< of those, with at least one sequence kept
  size_t sequences = 0, sprite_frames = 0;  ///< kept
  size_t cut_by_border = 0, two_people = 0, too_small = 0;  ///< person-frames left out
  /// Person-frames far taller, shorter or wider than their stretch's median (partly hidden, a
  /// part lost, someone passing close behind): they end the stretch too.
  size_t size_jumps = 0;
  /// Stretches as wide as two people for most of their frames (a pair walking side by side).
  size_t pairs = 0;
  size_t short_stretches = 0;   ///< unbroken stretches shorter than a gait cycle
};

class SpriteExtractor {
 public:
  /// `background`: the static scene (medianBackground of the video's frames).
  explicit SpriteExtractor(cv::Mat background, SpriteExtractionOptions options = {});
  ~SpriteExtractor();

  /// The video's next frame (BGR, the background's size).
  void add(const cv::Mat& bgr);
  /// The kept sequences, ordered by their first frame; `source` names the video in the bank.
  SpriteBank finish(const std::string& source);
  const SpriteExtractionReport& report() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dynslam::sim
