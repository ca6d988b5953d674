#include "SimulatedFrames.h"

#include <dynslam/core/Config.h>
#include <dynslam/testing/TestEnv.h>

#include <opencv2/imgproc.hpp>

namespace dynslam::frontend::testing {

sim::ScenarioOptions scenario(const std::string& name, const std::vector<std::string>& overrides) {
  sim::ScenarioOptions o;
  o.load(core::IniConfig::fromFile(dynslam::testing::sourceDir() + "/params/sim/" + name + ".ini",
                                   overrides));
  return o;
}

SimulatedFrame simulatedFrame(const sim::Simulator& sim, size_t index) {
  SimulatedFrame out;
  sim.renderFrame(index, out.truth);
  core::Frame& f = out.frame;
  f.index = index;
  f.t = sim.frameTime(index);
  f.rgb = out.truth.image.rgb;
  f.depth = out.truth.image.depth;
  f.intrinsics = sim.camera();
  f.T_body_camera = sim.T_body_camera();
  f.T_body_imu = sim.T_body_imu();
  const double t0 = index == 0 ? -1.0 : sim.frameTime(index - 1);
  for (const auto& m : sim.imu()) {
    if (m.t <= t0 || m.t > f.t) continue;
    core::ImuSample s;
    s.t = m.t;
    s.gyro = m.gyro;
    s.acc = m.acc;
    s.has_gyro = s.has_acc = true;
    f.imu.push_back(s);
  }
  return out;
}

std::vector<core::ObjectMask> truthMasks(const sim::SimFrame& truth) {
  std::vector<core::ObjectMask> masks;
  for (const auto& o : truth.objects) {
    if (o.visible_pixels == 0) continue;
    core::ObjectMask m;
    m.roi = o.box & cv::Rect(0, 0, truth.image.label.cols, truth.image.label.rows);
    m.mask = truth.image.label(m.roi) == o.id;
    m.valid = true;
    masks.push_back(m);
  }
  return masks;
}

}  // namespace dynslam::frontend::testing
