#pragma once
// Where the GNSS's local ENU frame lies in the estimator's world (method.md section 5, GNSS
// factor "ENU from the first fix"). The world is the first body pose, so ENU and world differ by
// a rigid transform T_world_enu, found once from pairs (antenna position the estimator holds,
// fix ENU) when the path spans enough:
// - with the IMU initialised, the world's gravity is known: ENU up is mapped onto -gravity and
//   only the rotation about it (yaw) and the translation are fitted (4 DoF). A straight drive is
//   enough.
// - without gravity (RGB-D only): Umeyama SE(3) on the pairs, which needs a path that is not a
//   line (a turn); until then there is no alignment and no GNSS factor.
// The alignment is not refined afterwards: a yaw error of the first span (VIO drift over
// min_span_m, well below a degree on the simulator) stays as a small rotation of the GNSS
// factors' targets. Refining it as a state of the window (as VINS-Fusion's global fusion does
// in a separate pose graph) is the next step if outdoor runs show it matters.
#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace dynslam::estimator {

struct GnssAlignmentParams {
  /// Horizontal extent (m) the pairs must span before the 4-DoF fit (largest distance of a
  /// pair from their centroid, in the plane orthogonal to gravity).
  double min_span_m = 5.0;
  /// Without gravity: the second singular value of the centred positions (m, RMS across the
  /// main direction) the SE(3) fit needs.
  double min_width_m = 2.0;
  int min_pairs = 10;
  /// Pairs kept while the path does not allow a fit (a robot standing still for hours): at this
  /// many, every second one is dropped, the first and the newest kept (the span stays whole).
  int max_pairs = 10000;
};

class GnssWorldAlignment {
 public:
  explicit GnssWorldAlignment(GnssAlignmentParams params = {}) : params_(params) {}

  /// One pair: the antenna's world position as the estimator has it, and the fix's ENU.
  void addPair(const Eigen::Vector3d& world_antenna, const Eigen::Vector3d& enu);

  /// Fits T_world_enu when the pairs allow it (see above); `world_gravity` when the IMU is
  /// initialised. Returns aligned(). Does nothing once aligned.
  bool tryAlign(const std::optional<Eigen::Vector3d>& world_gravity);

  bool aligned() const { return aligned_; }
  const Eigen::Isometry3d& T_world_enu() const { return T_world_enu_; }
  /// RMS distance (m) of the pairs after the fit.
  double rmsResidual() const { return rms_; }
  /// Pairs collected so far, or used by the fit once aligned.
  std::size_t pairs() const { return aligned_ ? pairs_used_ : world_.size(); }

 private:
  bool alignWithGravity(const Eigen::Vector3d& gravity);
  bool alignSe3();
  void finish(const Eigen::Isometry3d& T);

  GnssAlignmentParams params_;
  std::vector<Eigen::Vector3d> world_, enu_;
  Eigen::Isometry3d T_world_enu_ = Eigen::Isometry3d::Identity();
  bool aligned_ = false;
  double rms_ = 0;
  std::size_t pairs_used_ = 0;
};

}  // namespace dynslam::estimator
