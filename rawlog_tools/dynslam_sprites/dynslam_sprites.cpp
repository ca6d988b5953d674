// dynslam-sprites: a bank of real people's walking sequences cut from a static camera's video
// (SpriteExtractor.h), for the simulator's [People] appearance = video.
#include "SpriteContactSheet.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/sim/SpriteExtractor.h>
#include <opencv2/videoio.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace dynslam;

namespace {

const char* const kUsage =
    R"(usage: dynslam-sprites --video FILE --out DIR [--min-height PX] [--threshold T]
                       [--background-frames N] [--contact-sheet FILE.png]
       dynslam-sprites -h | --help

Cuts the people walking in front of a static camera out of its video into a sprite bank: the
median of sampled frames is the background, each frame's difference to it (cast shadows left
out) gives the people's blobs, which are followed over frames into walking sequences; per frame
a colour crop with its alpha mask and the foot point, in gait order. Left out: people cut by the
image border, blobs holding two people (two followed people share them, or they are as wide as
two), people shorter than --min-height, and unbroken stretches shorter than one gait cycle
(0.8 body heights walked). The same video gives the same
bank, byte for byte. Prints how many people, sequences and frames it kept and why it left the
others out.

Options:
  --video FILE            the video (any format OpenCV reads, e.g. Debian opencv-doc's
                          /usr/share/doc/opencv-doc/examples/data/vtest.avi)
  --out DIR               the bank's folder (created; its bank.txt is replaced)
  --min-height PX         people shorter than this in a frame are not kept there (default 80)
  --threshold T           grey levels a pixel must differ from the background by to be a
                          person's (default 30)
  --background-frames N   frames sampled evenly for the median background (default 60)
  --contact-sheet FILE.png
                          a picture of the bank: one row per sequence, up to eight of its
                          frames on grey, captioned with its length
  -h, --help              print this text and exit

Outputs: DIR/bank.txt (one line per frame: sequence frame video_frame crop_x crop_y foot_x
foot_y height_px walked_heights) and DIR/sNNN/fNNN.png (BGRA crops, alpha 255 on the person);
bank.txt is written last, so a folder without it is not a bank.
Exit codes: 0 written, 1 a video that cannot be read, holds no walking person, or an output
that cannot be written, 2 usage.
)";

cv::VideoCapture openVideo(const std::string& path) {
  if (!fs::is_regular_file(path)) throw std::runtime_error("--video " + path + ": no such file");
  cv::VideoCapture video(path);
  if (!video.isOpened())
    throw std::runtime_error("--video " + path + ": cannot open it as a video");
  return video;
}

/// Every `step`-th frame's copy for the median background.
std::vector<cv::Mat> sampleFrames(const std::string& path, int wanted) {
  cv::VideoCapture video = openVideo(path);
  const double reported = video.get(cv::CAP_PROP_FRAME_COUNT);
  const size_t step = std::max<size_t>(1, size_t(reported > 0 ? reported : 600) / size_t(wanted));
  std::vector<cv::Mat> samples;
  size_t count = 0;
  for (cv::Mat frame; video.read(frame); ++count) {
    if (frame.type() != CV_8UC3)
      throw std::runtime_error("--video " + path + ": frame " + std::to_string(count) +
                               " is not a colour image");
    if (count % step == 0) samples.push_back(frame.clone());
  }
  if (samples.empty()) throw std::runtime_error("--video " + path + ": holds no frame");
  return samples;
}

void printReport(const sim::SpriteExtractionReport& r) {
  std::printf(
      "kept %zu people of %zu followed: %zu sequences, %zu frames (of %zu video frames)\n"
      "left out: %zu person-frames cut by the border, %zu holding two people, %zu too small, "
      "%zu far off their stretch's size; %zu stretches of two people side by side, %zu shorter "
      "than a gait cycle\n",
      r.people, r.followed, r.sequences, r.sprite_frames, r.frames, r.cut_by_border, r.two_people,
      r.too_small, r.size_jumps, r.pairs, r.short_stretches);
}

int run(const core::CommandLine& cl) {
  const std::string videoPath = cl.required("--video"), out = cl.required("--out");
  sim::SpriteExtractionOptions options;
  options.min_height_px = int(cl.optionalInteger("--min-height").value_or(options.min_height_px));
  options.foreground.threshold = cl.optionalDouble("--threshold").value_or(30);
  const long long backgroundFrames = cl.optionalInteger("--background-frames").value_or(60);
  if (options.min_height_px < 8) throw core::UsageError("--min-height must be at least 8");
  if (backgroundFrames < 3) throw core::UsageError("--background-frames must be at least 3");
  // A failed run must not leave an earlier bank looking like this video's.
  fs::remove(fs::path(out) / "bank.txt");

  sim::SpriteExtractor extractor(
      sim::medianBackground(sampleFrames(videoPath, int(backgroundFrames))), options);
  cv::VideoCapture video = openVideo(videoPath);
  for (cv::Mat frame; video.read(frame);) extractor.add(frame);
  const sim::SpriteBank bank = extractor.finish(fs::path(videoPath).filename().string());
  printReport(extractor.report());
  if (bank.sequences.empty())
    throw std::runtime_error("--video " + videoPath +
                             ": no walking person kept (see the counts above; a static camera "
                             "and people at least --min-height tall are needed)");
  sim::writeSpriteBank(bank, out);
  std::printf("wrote %s/bank.txt\n", out.c_str());
  if (cl.has("--contact-sheet")) {
    const std::string sheet = cl.required("--contact-sheet");
    writeSpriteContactSheet(bank, sheet);
    std::printf("wrote %s\n", sheet.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("dynslam-sprites", [&] {
    core::CommandLine cl({"--video", "--out", "--min-height", "--threshold", "--background-frames",
                          "--contact-sheet"},
                         {}, {});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return run(cl);
  });
}
