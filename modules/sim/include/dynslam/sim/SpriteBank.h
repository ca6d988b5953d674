#pragma once
// A bank of real people's walking sequences cut from video (dynslam-sprites makes it): per frame
// a colour crop with its alpha mask (one BGRA PNG) and the foot point, in gait order, so the
// simulator can paste a real person's pixels onto a body-shaped surface and advance the walking
// cycle by the distance walked.
//
// On disk: DIR/bank.txt (one line per frame, below) and DIR/sNNN/fNNN.png (BGRA; alpha 255 on
// the person, 0 elsewhere). bank.txt:
//   # dynslam sprite bank v1
//   # source <video file name>
//   # sequence frame video_frame crop_x crop_y foot_x foot_y height_px walked_heights
//   0 0 112 406 215 31.5 142 140 0
//   ...
// crop_x/crop_y: the crop's top-left corner in the video frame; foot_x/foot_y: the point the
// person stands on, in the crop's pixels; height_px: the mask's
// height (head to foot); walked_heights: the foot's path length from the sequence's first frame,
// in units of the sequence's median height (a gait cycle is about 0.8 heights).
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace dynslam::sim {

struct SpriteFrame {
  int video_frame = 0;   ///< the frame of the source video it was cut from
  cv::Point crop_origin;  ///< the crop's top-left corner in the video frame
  cv::Mat bgra;          ///< CV_8UC4 crop; alpha 255 on the person
  cv::Point2f foot;      ///< where the person stands, crop pixels
  double height_px = 0;  ///< head to foot, pixels
  double walked_heights = 0;  ///< foot path length since the sequence's first frame / height
};

/// One person followed over consecutive frames, every frame kept (no gap, no second person).
struct SpriteSequence {
  std::vector<SpriteFrame> frames;
  /// Mean image motion of the foot per frame in the video, pixels (x > 0: to the right).
  cv::Point2f footVelocity() const;
};

struct SpriteBank {
  std::string source;  ///< the video's file name (no folder: the bank is the same wherever made)
  std::vector<SpriteSequence> sequences;
  size_t frameCount() const;
};

/// The point a person stands on in a mask (CV_8UC1, nonzero on the person): the mask's lowest
/// row, and its mean column in the lowest 3 % of its height (between the feet when they are
/// apart). SpriteFrame::foot is this point of the sprite's alpha.
cv::Point2f footPointOfMask(const cv::Mat& mask);

/// Writes DIR/bank.txt and the PNGs; creates DIR. Throws std::runtime_error naming the file
/// that cannot be written. bank.txt is written last, so a folder without it is not a bank.
void writeSpriteBank(const SpriteBank& bank, const std::string& dir);

/// Reads a bank written by writeSpriteBank. Throws std::runtime_error naming the folder, file
/// and line when it is missing, empty or malformed.
SpriteBank readSpriteBank(const std::string& dir);

}  // namespace dynslam::sim
