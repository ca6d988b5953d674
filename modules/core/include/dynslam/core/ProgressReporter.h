#pragma once
// Progress of a long run: a redrawn bar (frames/s, ETA) on a terminal, a plain line every few
// seconds otherwise (logs, CI), so both a person and a log reader see the run advancing.
#include <chrono>
#include <cstdio>
#include <string>

namespace dynslam::core {

class ProgressReporter {
 public:
  /// `interactive`: redraw one line in place (stderr is a terminal). Plain lines start with
  /// "[program]".
  ProgressReporter(std::FILE* out, bool interactive, double plain_interval_s = 5.0,
                   std::string program = "dynslam");

  /// frames done so far and the fraction of the input consumed, in [0, 1].
  void update(size_t frames, double fraction);
  /// Final line with totals.
  void finish(size_t frames);

  /// "12.3 fps", ETA "1m05s" etc. from the state so far.
  double framesPerSecond(size_t frames) const;
  static std::string formatDuration(double seconds);

 private:
  std::string line(size_t frames, double fraction) const;
  std::FILE* out_;
  bool interactive_;
  std::string program_;
  double interval_s_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace dynslam::core
