#pragma once
// The ObjectStates stage (ini section [ObjectStates]; not the method): a state a planner can
// trust for every tracked object, after the stage that poses the camera. Each confirmed track's
// mask gives its body centre in the world this frame (ObjectCentre.h); a constant-velocity
// Kalman filter per object (ConstantVelocityFilter.h) turns those into a centre, a velocity and
// their covariance. An object keeps its state while it is occluded or its track coasts, for up to
// max_coast_s; a new track that starts within reassociation_distance_m of such a state's
// prediction continues it under the same id (the tracker lost and re-made the object); a track
// whose measurements fall outside the filter's gate gate_frames times in a row (the tracker's id
// moved to another body) leaves its old state to coast and starts a new one; a single outlier
// (a mask cut by an occluder, another body's pixels) is skipped. Writes Frame::object_states.
#include <dynslam/core/Options.h>
#include <dynslam/core/Stage.h>
#include <dynslam/tracking/ConstantVelocityFilter.h>
#include <dynslam/tracking/ObjectCentre.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace dynslam::tracking {

/// [ObjectStates]: every key, its range and meaning in describe() (ObjectStateStage.cpp).
struct ObjectStateOptions : core::Options {
  ObjectCentreParams centre;
  double acceleration_sigma = 0.6;  ///< m/s^2/sqrt(Hz): how abruptly a body changes velocity
  /// A body whose recent measurements disagree with its state (the mean normalised innovation
  /// squared over about five frames above maneuver_nis) is turning or stopping: its state then
  /// moves with this acceleration noise instead, so the velocity follows within a few frames.
  double maneuver_acceleration_sigma = 4.0;
  double maneuver_nis = 6.0;         ///< 0 = off
  double initial_speed_sigma = 1.5;  ///< m/s; a new state's velocity sigma (it starts at rest)
  double max_coast_s = 1.0;
  double reassociation_distance_m = 0.6;
  double gate_chi2 = 16.27;  ///< 3 dof, p = 0.001; 0 = off
  int gate_frames = 3;       ///< outliers in a row that part a track from its state
  double moving_speed = 0.25;
  bool confirmed_only = true;
  double extent_smoothing = 0.2;  ///< weight of a new measurement in the extent's running mean

  void describe(core::OptionVisitor& v) override;
};

class ObjectStateStage : public core::Stage {
 public:
  ObjectStateStage() = default;
  explicit ObjectStateStage(const ObjectStateOptions& options) : options_(options) {}

  void configure(const core::IniConfig& cfg, const std::string& section) override;
  void process(core::Frame& frame) override;
  void finish() override;
  std::vector<std::pair<std::string, double>> statistics() const override;

 private:
  struct Followed {
    int id = -1, track_id = -1;
    std::string category;
    ConstantVelocityFilter filter;
    Eigen::Vector3d extent;
    double last_measured = 0;
    bool measured = false;
    int outliers = 0;  // the track's measurements outside the gate in a row
    double nis = 0;    // fading mean of the normalised innovation squared (3 when consistent)
  };
  struct Measurement {
    int track_id = -1;
    std::string category;
    Eigen::Vector3d centre;  // world
    Eigen::Matrix3d covariance;
    Eigen::Vector3d extent;
    int points = 0;
  };

  std::vector<Measurement> measure(const core::Frame& frame, const Eigen::Vector3d& up_world) const;
  void associate(std::vector<Measurement>& measurements, double t);
  /// `nis`: the measurement's squared Mahalanobis distance from the state before the update.
  void update(Followed& state, const Measurement& m, double nis, double t);
  Eigen::Vector3d horizontal(const Eigen::Vector3d& v) const;  ///< v without its part along up
  std::vector<core::ObjectState> states() const;

  ObjectStateOptions options_;
  std::vector<Followed> followed_;
  std::set<int> followed_tracks_;  // every track id a state has followed
  std::optional<double> last_t_;
  Eigen::Vector3d up_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitZ();
  int next_id_ = 0;
  std::size_t frames_ = 0, measurements_ = 0, reassociated_ = 0, gated_ = 0, expired_ = 0,
              predictions_ = 0, maneuvering_ = 0;  // state predictions, with manoeuvre noise
};

}  // namespace dynslam::tracking
