// Render speed of the simulator (issue 3: >= 60 frames/s at 640x480 for indoor_people on the
// 2-core machine). Renders frames of each scenario exactly as dynslam-sim does (rasterizer,
// sensor noise, per-object ground truth) without writing files, and prints frames/s.
//
//   build/bin/bench-sim-render [--config params/sim/A.ini]... [--frames 300] [--set s.k=v]...
// Without --config: indoor_people_high, market_crowd_high and outdoor_street_high.
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/sim/Simulator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

namespace {

void benchmark(const std::string& ini, const std::vector<std::string>& overrides,
               size_t maxFrames) {
  using namespace dynslam;
  sim::ScenarioOptions options;
  options.load(core::IniConfig::fromFile(ini, overrides));
  const auto setupStart = std::chrono::steady_clock::now();
  const sim::Simulator simulator(options);
  const double setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();
  const size_t frames = std::min(simulator.frameCount(), maxFrames);

  std::vector<double> ms;
  sim::SimFrame frame;
  size_t objects = 0;
  for (size_t i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    simulator.renderFrame(i, frame);
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    for (const auto& o : frame.objects) objects += o.visible_pixels > 0;
  }
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  double total = 0;
  for (double m : ms) total += m;
  std::printf("scenario        %s\n", ini.c_str());
  std::printf("image           %dx%d\n", options.world.width, options.world.height);
  std::printf("frames          %zu (%.1f objects visible on average)\n", frames,
              frames ? double(objects) / frames : 0.0);
  std::printf("scene set-up    %.2f s (textures, geometry, IMU for the whole sequence)\n", setup);
  std::printf("per frame       median %.2f ms, p90 %.2f ms, max %.2f ms\n",
              sorted[sorted.size() / 2], sorted[sorted.size() * 9 / 10], sorted.back());
  std::printf("render speed    %.1f frames/s (target >= 60; ratio %.2f)\n\n",
              1000.0 * frames / total, 1000.0 * frames / total / 60.0);
}

const char* const kUsage =
    R"(usage: bench-sim-render [--config params/sim/NAME.ini]... [--frames N] [--set S.k=v]...
       bench-sim-render -h | --help

Renders frames of each scenario exactly as dynslam-sim does (rasterizer, sensor noise,
per-object ground truth) without writing files, and prints per scenario: the image size, the
frames and objects visible, the scene's set-up time, the median / p90 / max time per frame and
the render speed in frames/s against the 60 frames/s target. Run from the source tree (the
default scenarios are relative paths).

Options:
  --config FILE.ini   a scenario (repeatable; default: params/sim/indoor_people_high.ini,
                      market_crowd_high.ini and outdoor_street_high.ini)
  --frames N          frames rendered per scenario at most (default 300)
  --set S.k=v         override a scenario key (repeatable), as dynslam-sim's --set
  -h, --help          print this text and exit

Exit codes: 0 done, 1 a bad scenario, 2 usage.
)";

}  // namespace

int main(int argc, char** argv) {
  using namespace dynslam;
  return core::runProgram("bench-sim-render", [&] {
    core::CommandLine cl({"--frames"}, {}, {"--config", "--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    std::vector<std::string> inis = cl.all("--config");
    if (inis.empty())
      inis = {"params/sim/indoor_people_high.ini", "params/sim/market_crowd_high.ini",
              "params/sim/outdoor_street_high.ini"};
    const auto frames = static_cast<size_t>(cl.optionalInteger("--frames").value_or(300));
    for (const auto& ini : inis) benchmark(ini, cl.all("--set"), frames);
    return 0;
  });
}
