// Feeds a rawlog's observations one by one into dynslam::system::System, as a sensor driver
// would, prints each second's pose and the moving objects, and writes the camera trajectory.
//   embed CONFIG.ini RAWLOG OUT.tum [section.key=value ...]
#include <dynslam/core/Frame.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/system/System.h>

#include <mrpt/obs/CObservation.h>

#include <cstdio>
#include <fstream>
#include <memory>

using namespace dynslam::system;

/// The camera poses as TUM lines, exactly as `dynslam` writes trajectory.tum.
struct TumSink : FrameSink {
  explicit TumSink(const char* path) : out(path) {}
  void onFrame(const dynslam::core::Frame& f, const FrameContext&) override {
    if (f.T_world_camera) dynslam::core::appendTumLine(out, {f.t, *f.T_world_camera});
  }
  std::ofstream out;
};

int main(int argc, char** argv) try {
  if (argc < 4)
    return std::fprintf(stderr, "usage: embed CONFIG.ini RAWLOG OUT.tum [s.k=v ...]\n"), 2;
  System slam(argv[1], std::vector<std::string>(argv + 4, argv + argc));
  slam.addSink(std::make_shared<TumSink>(argv[3]));
  int poses = 0;
  slam.subscribeToLocalization([&](const LocalizationUpdate& u) {
    if (poses++ % 30 == 0) std::printf("pose %s\n", u.pose.asString().c_str());
  });
  dynslam::io::RawlogSource rawlog(argv[2]);
  while (auto observation = rawlog.next()) slam.onNewObservation(observation);
  slam.flush();
  for (const MovingObject& o : slam.movingObjects())
    std::printf("object %d %s at %s, %.2f m/s\n", o.id, o.category.c_str(),
                o.pose.asString().c_str(), o.velocity.norm());
  std::printf("%d poses, status %s\n", poses, toString(slam.status()));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "embed: %s\n", e.what());
  return 1;
}
