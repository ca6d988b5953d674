#include "OpenCvDocImages.h"

#include <opencv2/videoio.hpp>

#include <filesystem>

namespace dynslam::detection::testing {

std::string openCvDocFile(const std::string& name) {
  const std::string path = "/usr/share/doc/opencv-doc/examples/data/" + name;
  return std::filesystem::exists(path) ? path : "";
}

std::vector<cv::Mat> vtestFrames(const std::vector<int>& indices) {
  cv::VideoCapture video(openCvDocFile("vtest.avi"));
  std::vector<cv::Mat> frames;
  if (!video.isOpened()) return frames;
  for (const int i : indices) {
    video.set(cv::CAP_PROP_POS_FRAMES, i);
    cv::Mat frame;
    if (!video.read(frame) || frame.empty()) return {};
    frames.push_back(frame);
  }
  return frames;
}

}  // namespace dynslam::detection::testing
