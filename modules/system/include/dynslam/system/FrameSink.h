#pragma once
// The outputs of a run as plug-ins: System hands every processed frame to each sink it was
// given, in frame order, on its processing thread. The dynslam program's files (trajectory,
// objects, timing, keyframes, annotated frames, map, live view) are sinks; an embedding
// program adds those it wants, or its own.
namespace dynslam::core {
struct Frame;
class Pipeline;
}  // namespace dynslam::core

namespace dynslam::system {

/// What a sink may read besides the frame.
struct FrameContext {
  const core::Pipeline& pipeline;  ///< each stage's time and statistics for this frame
  double process_ms = 0;           ///< wall time the pipeline took for the frame
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// One processed frame. An exception stops the run as a stage's would.
  virtual void onFrame(const core::Frame& frame, const FrameContext& context) = 0;
  /// The stream ended (System::flush) or was stopped: write what is pending. Called once.
  virtual void onEnd() {}
};

}  // namespace dynslam::system
