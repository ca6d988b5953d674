#pragma once
// GNSS in the estimator (method.md section 5, "GNSS (beyond the paper)"): turns the frames' fixes
// into position targets for the window's keyframes. Fixes are buffered and interpolated to each
// keyframe's time (GnssFixBuffer); until the ENU frame's place in the world is known, the pairs
// (keyframe antenna position as estimated, interpolated fix) go to GnssWorldAlignment; from then
// on each keyframe gets its fix in world coordinates with a covariance from the fix's HDOP.
// The window turns targets into GnssPositionFactor (lever arm: SlidingWindowParams).
#include <dynslam/core/Frame.h>
#include <dynslam/estimator/GnssFixBuffer.h>
#include <dynslam/estimator/GnssWorldAlignment.h>

#include <Eigen/Geometry>

#include <deque>
#include <optional>
#include <vector>

namespace dynslam::estimator {

struct GnssAnchorParams {
  /// Horizontal standard deviation of a fix at HDOP 1 (m; the receiver's UERE): 2-5 m for a plain
  /// GPS, centimetres for RTK. The fix's sigma is this times its HDOP (times 1 when not given).
  double uere_horizontal_m = 2.0;
  double vertical_factor = 2.0;  ///< vertical sigma = this x horizontal (GNSS heights are worse)
  double max_gap_s = 0.5;        ///< no interpolation across a longer dropout
  GnssAlignmentParams alignment;
};

struct GnssTarget {
  double t = 0;                                     ///< keyframe time
  Eigen::Vector3d world = Eigen::Vector3d::Zero();  ///< antenna position, world frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

class GnssAnchor {
 public:
  explicit GnssAnchor(GnssAnchorParams params = {});

  void addFixes(const std::vector<core::GnssFix>& fixes);
  /// A keyframe at time t was added to the window: it waits for the fix after t.
  void keyframeAdded(double t);

  /// The targets of the pending keyframes whose fixes have arrived. `antennaAt(t)` gives the
  /// window's estimate of the antenna's world position at keyframe time t (nothing when the
  /// keyframe has left the window); `gravity` the world gravity once the IMU is initialised.
  template <class AntennaAt>
  std::vector<GnssTarget> resolve(AntennaAt antennaAt,
                                  const std::optional<Eigen::Vector3d>& gravity);

  bool aligned() const { return alignment_.aligned(); }
  const GnssWorldAlignment& alignment() const { return alignment_; }

 private:
  Eigen::Matrix3d covariance(double hdop) const;

  GnssAnchorParams params_;
  GnssFixBuffer fixes_;
  GnssWorldAlignment alignment_;
  std::deque<double> pending_;
  double latest_keyframe_ = 0;
};

template <class AntennaAt>
std::vector<GnssTarget> GnssAnchor::resolve(AntennaAt antennaAt,
                                            const std::optional<Eigen::Vector3d>& gravity) {
  std::vector<GnssTarget> targets;
  while (!pending_.empty() && fixes_.covers(pending_.front())) {
    const double t = pending_.front();
    pending_.pop_front();
    const auto fix = fixes_.at(t);
    if (!fix) continue;  // before the first fix, or inside a dropout
    if (!alignment_.aligned()) {
      if (const std::optional<Eigen::Vector3d> antenna = antennaAt(t))
        alignment_.addPair(*antenna, fix->enu);
      alignment_.tryAlign(gravity);
      continue;
    }
    const Eigen::Matrix3d R = alignment_.T_world_enu().linear();
    targets.push_back(
        {t, alignment_.T_world_enu() * fix->enu, R * covariance(fix->hdop) * R.transpose()});
  }
  fixes_.dropBefore(pending_.empty() ? latest_keyframe_ : pending_.front());
  return targets;
}

}  // namespace dynslam::estimator
