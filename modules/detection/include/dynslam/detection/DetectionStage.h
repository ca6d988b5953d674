#pragma once
// The detection stage (class "Detection", section [Detection]): runs the detector `detector`
// names (onnx_yolo | hog | ground_truth) and fills Frame::detections.
//  - mode = deterministic: the detector runs on every frame, inline; detections_fresh = true.
//  - mode = realtime: the detector runs in its own thread at its own rate (RealtimeDetector),
//    always on the newest frame. A frame gets the newest result finished since the previous
//    frame (detections_fresh = true), computed on an earlier frame's image (sourceFrames() says
//    which); any other frame gets no detections and detections_fresh = false, and the tracker's
//    predicted boxes stand in. The stage never waits for the detector.
#include <dynslam/core/Stage.h>
#include <dynslam/detection/DetectionOptions.h>

#include <memory>

namespace dynslam::detection {

class Detector;
class RealtimeDetector;

class DetectionStage : public core::Stage {
 public:
  DetectionStage();
  ~DetectionStage() override;

  /// ConfigError naming the section, key and source for an unknown detector, mode, layout or a
  /// bad class map, and for a detector that cannot start (e.g. a missing model file).
  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  /// fresh_frames, frames; in real-time mode also detector_runs, detector_hz (runs per second
  /// of stream time: the detector thread's rate when the stream is played at camera rate),
  /// detector_ms (mean per run) and superseded (results a newer one replaced).
  std::vector<std::pair<std::string, double>> statistics() const override;

  const DetectionOptions& options() const { return options_; }
  std::size_t frames() const { return frames_; }
  std::size_t freshFrames() const { return fresh_frames_; }  ///< frames given a result
  /// In real-time mode: the frame index of the image each fresh frame's detections came from,
  /// in delivery order (deterministic mode: the frame itself); of a long run, the newest
  /// kSourceFramesKept to twice that many.
  const std::vector<std::size_t>& sourceFrames() const { return source_frames_; }
  static constexpr std::size_t kSourceFramesKept = 10000;

 private:
  std::unique_ptr<Detector> makeDetector(const core::IniConfig& cfg,
                                         const std::string& section) const;
  void recordSource(std::size_t frame_index);

  DetectionOptions options_;
  std::unique_ptr<Detector> detector_;          // deterministic mode
  std::unique_ptr<RealtimeDetector> realtime_;  // real-time mode
  std::size_t frames_ = 0, fresh_frames_ = 0;
  std::vector<std::size_t> source_frames_;
  double realtime_detector_seconds_ = 0;
  double first_t_ = 0, last_t_ = 0;
  std::vector<std::pair<std::string, double>> statistics_;  // filled by finish()
};

}  // namespace dynslam::detection
