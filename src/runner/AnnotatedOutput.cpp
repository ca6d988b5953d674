#include "AnnotatedOutput.h"

#include <dynslam/viz/AnnotatedFrame.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::runner {

AnnotatedOutput::AnnotatedOutput(std::string dir, bool video)
    : dir_(std::move(dir)), video_(video) {}

AnnotatedOutput::~AnnotatedOutput() = default;

void AnnotatedOutput::write(const core::Frame& frame) {
  const cv::Mat img = viz::renderAnnotatedFrame(frame);
  char name[32];
  std::snprintf(name, sizeof name, "%06zu.png", frame.index);
  const std::string path = (fs::path(dir_) / name).string();
  if (!cv::imwrite(path, img))
    throw std::runtime_error("cannot write the annotated frame '" + path + "'");
  if (!video_) return;
  if (!writer_) {
    if (first_.empty()) {
      first_ = img;
      first_t_ = frame.t;
      return;
    }
    // The camera's rate from the first two stamps (30 Hz when they make no sense).
    const double dt = frame.t - first_t_;
    openVideo(dt > 1e-3 && dt < 10 ? 1.0 / dt : 30.0);
    writer_->write(first_);
    first_.release();
  }
  if (img.size() != first_size_) {
    cv::Mat resized;
    cv::resize(img, resized, first_size_);
    writer_->write(resized);
  } else {
    writer_->write(img);
  }
}

void AnnotatedOutput::finish() {
  if (!video_) return;
  if (!writer_ && !first_.empty()) {
    openVideo(30.0);
    writer_->write(first_);
    first_.release();
  }
  if (writer_) writer_->release();
}

void AnnotatedOutput::openVideo(double fps) {
  const std::string path = (fs::path(dir_) / kVideoName).string();
  first_size_ = first_.size();
  writer_ = std::make_unique<cv::VideoWriter>(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                                              fps, first_size_);
  if (!writer_->isOpened()) throw std::runtime_error("cannot write the video '" + path + "'");
}

}  // namespace dynslam::runner
