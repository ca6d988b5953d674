#pragma once
// --frames DIR: the annotated picture of every frame (viz::renderAnnotatedFrame) as
// DIR/NNNNNN.png and, one after the other, as the video DIR/annotated.avi (Motion-JPEG, which
// OpenCV writes itself: no FFmpeg needed, and VLC, mpv and ffplay play it).
#include <dynslam/core/Frame.h>
#include <dynslam/system/FrameSink.h>

#include <memory>
#include <string>

namespace cv {
class VideoWriter;
}

namespace dynslam::runner {

class AnnotatedOutput : public system::FrameSink {
 public:
  static constexpr const char* kVideoName = "annotated.avi";

  /// `video` false: PNGs only.
  AnnotatedOutput(std::string dir, bool video);
  ~AnnotatedOutput();

  /// Throws std::runtime_error naming the file it could not write.
  void write(const core::Frame& frame);
  /// Writes a frame held back for the video's rate (a one-frame run) and closes the video.
  void finish();
  void onFrame(const core::Frame& frame, const system::FrameContext&) override { write(frame); }
  void onEnd() override { finish(); }

 private:
  void openVideo(double fps);

  std::string dir_;
  bool video_;
  std::unique_ptr<cv::VideoWriter> writer_;
  cv::Mat first_;  ///< held until the second frame's stamp gives the video's frame rate
  double first_t_ = 0;
  cv::Size first_size_;  ///< the video's size; a frame of another size is scaled to it
};

}  // namespace dynslam::runner
