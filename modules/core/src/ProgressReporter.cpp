#include "dynslam/core/ProgressReporter.h"

#include <algorithm>
#include <cmath>

namespace dynslam::core {
namespace {
double secondsBetween(std::chrono::steady_clock::time_point a,
                      std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

ProgressReporter::ProgressReporter(std::FILE* out, bool interactive, double plain_interval_s,
                                   std::string program)
    : out_(out),
      interactive_(interactive),
      program_(std::move(program)),
      interval_s_(plain_interval_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

double ProgressReporter::framesPerSecond(size_t frames) const {
  const double s = secondsBetween(start_, std::chrono::steady_clock::now());
  return s > 0 ? frames / s : 0.0;
}

std::string ProgressReporter::formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s / 60) % 60);
  else if (s >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", s);
  return buf;
}

std::string ProgressReporter::line(size_t frames, double fraction) const {
  const double elapsed = secondsBetween(start_, std::chrono::steady_clock::now());
  const double eta = fraction > 0.001 ? elapsed * (1.0 - fraction) / fraction : NAN;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%3.0f%% | %zu frames | %.1f fps | elapsed %s | ETA %s",
                100.0 * fraction, frames, framesPerSecond(frames), formatDuration(elapsed).c_str(),
                formatDuration(eta).c_str());
  return buf;
}

void ProgressReporter::update(size_t frames, double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const auto now = std::chrono::steady_clock::now();
  if (interactive_) {
    if (drawn_ && secondsBetween(last_, now) < 0.1) return;  // redraw at most 10 times a second
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(out_, "\r[%s%s] %s\033[K", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), line(frames, fraction).c_str());
    std::fflush(out_);
    drawn_ = true;
    last_ = now;
  } else if (secondsBetween(last_, now) >= interval_s_) {
    std::fprintf(out_, "[%s] %s\n", program_.c_str(), line(frames, fraction).c_str());
    std::fflush(out_);
    last_ = now;
  }
}

void ProgressReporter::finish(size_t frames) {
  if (interactive_ && drawn_) std::fprintf(out_, "\n");
  const double elapsed = secondsBetween(start_, std::chrono::steady_clock::now());
  std::fprintf(out_, "[%s] processed %zu frames in %s (%.1f fps)\n", program_.c_str(), frames,
               formatDuration(elapsed).c_str(), framesPerSecond(frames));
  std::fflush(out_);
}

}  // namespace dynslam::core
