#pragma once
// GNSS fixes come at their own rate (10-20 Hz) and not at keyframe times; the GNSS factor sits
// on a keyframe pose. The buffer interpolates the ENU position linearly between the two fixes
// that bracket a keyframe's time (a car at 8 m/s moves 0.4 m between 10 Hz fixes, so the
// nearest fix alone would be off by up to 0.4 m; the linear interpolation's error is the
// acceleration's, millimetres). A keyframe whose later fix has not arrived yet waits for it.
#include <Eigen/Core>

#include <deque>
#include <optional>

namespace dynslam::estimator {

class GnssFixBuffer {
 public:
  /// `max_gap_s`: fixes further apart than this are not interpolated between (a dropout).
  explicit GnssFixBuffer(double max_gap_s = 0.5) : max_gap_s_(max_gap_s) {}

  struct Position {
    Eigen::Vector3d enu;
    double hdop;  ///< the larger of the bracketing fixes' (0 = not reported)
  };

  /// Adds a fix; fixes must come in time order (an older one is ignored).
  void add(double t, const Eigen::Vector3d& enu, double hdop = 0);

  /// ENU at time `t` interpolated between the bracketing fixes; nothing when no fix is at or
  /// after `t` yet, none is at or before it, or they are more than max_gap_s apart.
  std::optional<Position> at(double t) const;

  /// True when a fix at or after `t` has arrived (at(t) will not change any more).
  bool covers(double t) const { return !fixes_.empty() && fixes_.back().t >= t; }

  /// Drops fixes no longer needed for times >= t.
  void dropBefore(double t);

  std::size_t size() const { return fixes_.size(); }

 private:
  struct Fix {
    double t;
    Eigen::Vector3d enu;
    double hdop;
  };
  double max_gap_s_;
  std::deque<Fix> fixes_;
};

}  // namespace dynslam::estimator
