#pragma once
// trajectory.tum (the camera, pose by pose, flushed as it goes: a run that fails part-way keeps
// every pose before the failure) and objects/<id>.tum: each object state's centre when the
// pipeline has the ObjectStates stage (id: the state's), else each object the estimator poses.
#include <dynslam/io/TrajectoryWriter.h>
#include <dynslam/system/FrameSink.h>

#include <cstddef>
#include <set>
#include <string>

namespace dynslam::runner {

class TrajectoryFiles : public system::FrameSink {
 public:
  /// Creates (truncates) OUT/trajectory.tum; throws std::runtime_error naming it on failure.
  explicit TrajectoryFiles(const std::string& out);

  void onFrame(const core::Frame& frame, const system::FrameContext& context) override;

  const io::TumTrajectoryWriter& trajectory() const { return trajectory_; }
  /// Objects with a trajectory file written this run.
  std::size_t objects() const { return created_.size(); }

 private:
  void appendObjectPose(int id, const core::StampedPose& pose);

  std::string out_;
  io::TumTrajectoryWriter trajectory_;
  std::set<int> created_;  // ids whose objects/<id>.tum this run has created
};

}  // namespace dynslam::runner
