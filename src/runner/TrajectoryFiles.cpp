#include "TrajectoryFiles.h"

#include <dynslam/core/Frame.h>
#include <dynslam/core/TrajectoryFile.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::runner {

TrajectoryFiles::TrajectoryFiles(const std::string& out)
    : out_(out), trajectory_((fs::path(out) / "trajectory.tum").string()) {}

void TrajectoryFiles::onFrame(const core::Frame& frame, const system::FrameContext&) {
  if (frame.T_world_camera) trajectory_.append({frame.t, *frame.T_world_camera});
  if (frame.object_states) {
    // The ObjectStates stage ran: each file follows a state's centre (the world's axes).
    for (const auto& state : *frame.object_states) {
      Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
      T.translation() = state.centre;
      appendObjectPose(state.id, {frame.t, T});
    }
    return;
  }
  for (const auto& object : frame.object_poses)
    appendObjectPose(object.object_id, {frame.t, object.T_world_object});
}

/// Opened and closed per line: a long run follows thousands of objects, and one open stream
/// each would hold a buffer and a file descriptor per object for the whole run (the
/// 10,000-frame soak grew by 5 MB with 525 of them open).
void TrajectoryFiles::appendObjectPose(int id, const core::StampedPose& pose) {
  const fs::path dir = fs::path(out_) / "objects";
  const bool first = created_.insert(id).second;
  if (first) fs::create_directories(dir);
  const std::string path = (dir / (std::to_string(id) + ".tum")).string();
  std::ofstream file(path, first ? std::ios::trunc : std::ios::app);
  core::appendTumLine(file, pose);
  if (!file) throw std::runtime_error("cannot write the object trajectory '" + path + "'");
}

}  // namespace dynslam::runner
