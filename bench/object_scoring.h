#pragma once
// Scoring object states (objects/states.csv) against the simulator's objects.txt, as a planner
// uses them: in the camera's frame (each state through the estimated camera pose, each true body
// through the true one), on the ground plane (the true world's z is up). Per frame the states
// are paired with the bodies in view by least total distance (Hungarian) within a gate; what is
// scored is every walking person in view (objects.txt: person, moving, visible fraction at least
// min_visible):
//   - position: the paired state's centre against the torso centre, horizontal distance;
//   - velocity: against the torso's central difference over +-velocity_frames frames;
//   - id switches: a person paired with another state id than the one it was paired with last;
//   - without a state: frames in view unpaired, and each person's longest such stretch.
#include <dynslam/core/ObjectGroundTruth.h>
#include <dynslam/core/ObjectState.h>
#include <dynslam/core/Trajectory.h>

#include <map>
#include <string>
#include <vector>

namespace dynslam::bench {

struct ObjectScoringOptions {
  double gate_m = 1.0;       ///< a state farther than this from a body is not paired with it
  double min_visible = 0.3;  ///< visible fraction from which a walking person counts as in view
  int velocity_frames = 3;   ///< the true velocity's half window, frames
  double stamp_tolerance = 1e-3;
};

/// objects/states.csv by frame stamp; throws std::runtime_error naming the file and line.
std::map<double, std::vector<core::ObjectState>> readObjectStates(const std::string& path);

struct ObjectScore {
  std::vector<double> position_errors;  ///< m, one per scored frame and person paired
  std::vector<double> velocity_errors;  ///< m/s
  int scored = 0;                       ///< walking-person frames in view
  int paired = 0;
  int id_switches = 0;
  int persons = 0;                   ///< walking persons ever in view
  std::vector<double> longest_gaps;  ///< s, per person: longest stretch in view without a state
  double frame_interval = 0;         ///< s, median of the truth's
};

/// Scores one run: `truth` (objects.txt rows), the true and the estimated camera trajectories,
/// the states by stamp.
ObjectScore scoreObjectStates(const std::vector<core::ObjectGroundTruthRow>& truth,
                              const core::Trajectory& true_camera,
                              const core::Trajectory& estimated_camera,
                              const std::map<double, std::vector<core::ObjectState>>& states,
                              const ObjectScoringOptions& options = {});

/// `b` appended to `a` (pooling runs).
void pool(ObjectScore& a, const ObjectScore& b);

/// A top view (PNG) of one run in the true world: the camera's path (black), each walking
/// person's torso path (grey) and every state's centre placed by the frame's camera poses (the
/// estimated one's offset applied to the true one), a colour per state id; hollow where the
/// state was predicted. Throws std::runtime_error naming the file when it cannot be written.
void writeTopView(const std::string& path, const std::vector<core::ObjectGroundTruthRow>& truth,
                  const core::Trajectory& true_camera, const core::Trajectory& estimated_camera,
                  const std::map<double, std::vector<core::ObjectState>>& states,
                  const ObjectScoringOptions& options = {});

}  // namespace dynslam::bench
