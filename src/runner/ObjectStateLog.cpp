#include "ObjectStateLog.h"

#include <dynslam/core/Frame.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <stdexcept>

namespace dynslam::runner {

void ObjectStateLog::onFrame(const core::Frame& frame, const system::FrameContext&) {
  if (!frame.object_states) return;
  if (!out_.is_open()) {
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path());
    out_.open(path_, std::ios::trunc);
    out_ << "t_s,id,track_id,category,measured,moving,x,y,z,vx,vy,vz,width,depth,height,"
            "sigma_x,sigma_y,sigma_z,sigma_vx,sigma_vy,sigma_vz,up_x,up_y,up_z\n";
  }
  for (const auto& s : *frame.object_states) {
    out_ << std::fixed << std::setprecision(6) << frame.t << ',' << s.id << ',' << s.track_id << ','
         << s.category << ',' << int(s.measured) << ',' << int(s.moving) << std::setprecision(4);
    for (const auto* v : {&s.centre, &s.velocity, &s.extent})
      out_ << ',' << (*v)(0) << ',' << (*v)(1) << ',' << (*v)(2);
    for (int i = 0; i < 6; ++i) out_ << ',' << std::sqrt(std::max(0.0, s.covariance(i, i)));
    out_ << ',' << s.up(0) << ',' << s.up(1) << ',' << s.up(2) << '\n';
  }
  // Flushed per frame, as keyframes.csv: a kill -9 leaves every frame before it whole.
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write the object states '" + path_ + "'");
}

}  // namespace dynslam::runner
