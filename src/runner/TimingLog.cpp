#include "TimingLog.h"

#include <dynslam/core/Frame.h>
#include <dynslam/core/Pipeline.h>

#include <iomanip>
#include <stdexcept>

namespace dynslam::runner {

TimingLog::TimingLog(const std::string& path, const core::Pipeline& pipeline)
    : path_(path), out_(path, std::ios::trunc) {
  out_ << "frame,t_s";
  for (const auto& stage : pipeline.times()) out_ << ',' << stage.name << "_ms";
  out_ << ",pipeline_ms\n";
  if (!out_) throw std::runtime_error("cannot write the timing log '" + path + "'");
}

void TimingLog::append(std::size_t frame, double t, const core::Pipeline& pipeline,
                       double pipeline_ms) {
  out_ << frame << ',' << std::fixed << std::setprecision(6) << t << std::setprecision(3);
  for (const auto& stage : pipeline.times()) out_ << ',' << stage.ms.last();
  out_ << ',' << pipeline_ms << '\n';
  // Flushed per row, one write() a row: a kill -9 leaves every row before it whole (flushed
  // only when the buffer filled, the last row could be cut anywhere).
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write the timing log '" + path_ + "'");
}

void TimingLog::onFrame(const core::Frame& frame, const system::FrameContext& context) {
  append(frame.index, frame.t, context.pipeline, context.process_ms);
}

}  // namespace dynslam::runner
