#pragma once
// objects/states.csv: every object state of every frame (the ObjectStates stage; a planner's
// view of the moving objects), one row per frame and object, flushed per frame:
//   t_s,id,track_id,category,measured,moving,x,y,z,vx,vy,vz,width,depth,height,
//   sigma_x,sigma_y,sigma_z,sigma_vx,sigma_vy,sigma_vz,up_x,up_y,up_z
// in the world frame of trajectory.tum. Created at the first frame that carries states: a
// pipeline without the stage writes no file.
#include <dynslam/system/FrameSink.h>

#include <fstream>
#include <string>

namespace dynslam::runner {

class ObjectStateLog : public system::FrameSink {
 public:
  explicit ObjectStateLog(std::string path) : path_(std::move(path)) {}

  /// Throws std::runtime_error naming the file when it cannot be written.
  void onFrame(const core::Frame& frame, const system::FrameContext&) override;

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace dynslam::runner
