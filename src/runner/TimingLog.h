#pragma once
// timing.csv: one row per frame, the wall time of every stage on it (ms), for plots of where
// the time goes over a run (summary.json keeps only the medians).
//   frame,t_s,Detection_ms,...,Estimator_ms,pipeline_ms
#include <dynslam/system/FrameSink.h>

#include <fstream>
#include <string>
#include <vector>

namespace dynslam::core {
class Pipeline;
}

namespace dynslam::runner {

class TimingLog : public system::FrameSink {
 public:
  /// Creates (truncates) `path` and writes the header from the pipeline's stage names. Throws
  /// std::runtime_error naming the file when it cannot be written.
  TimingLog(const std::string& path, const core::Pipeline& pipeline);

  /// One row: the last time each stage recorded (the frame just processed) and the whole
  /// pipeline's wall time on it.
  void append(std::size_t frame, double t, const core::Pipeline& pipeline, double pipeline_ms);
  void onFrame(const core::Frame& frame, const system::FrameContext& context) override;

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace dynslam::runner
