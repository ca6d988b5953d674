// Render speed of the simulator (issue 3: >= 60 frames/s at 640x480 for indoor_people on the
// 2-core machine). Renders frames of a scenario exactly as dynslam-sim does (rasterizer, sensor
// noise, per-object ground truth) without writing files, and prints frames/s.
//
//   build/bin/bench-sim-render [--config params/sim/indoor_people_high.ini] [--frames 300]
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/sim/Simulator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  using namespace dynslam;
  return core::runProgram("bench-sim-render", [&] {
    core::CommandLine cl({"--config", "--frames"}, {}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << "usage: bench-sim-render [--config INI] [--frames N] [--set s.k=v]...\n";
      return 0;
    }
    const std::string ini = cl.valueOr("--config", "params/sim/indoor_people_high.ini");
    sim::ScenarioOptions options;
    options.load(core::IniConfig::fromFile(ini, cl.all("--set")));
    const auto setupStart = std::chrono::steady_clock::now();
    const sim::Simulator simulator(options);
    const double setup =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();
    const size_t frames =
        std::min<size_t>(simulator.frameCount(), cl.optionalInteger("--frames").value_or(300));

    std::vector<double> ms;
    sim::SimFrame frame;
    size_t objects = 0;
    for (size_t i = 0; i < frames; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      simulator.renderFrame(i, frame);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                       .count());
      objects += frame.objects.size();
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    double total = 0;
    for (double m : ms) total += m;
    std::printf("scenario        %s\n", ini.c_str());
    std::printf("image           %dx%d\n", options.world.width, options.world.height);
    std::printf("frames          %zu (%.1f objects in view on average)\n", frames,
                frames ? double(objects) / frames : 0.0);
    std::printf("scene set-up    %.2f s (textures, geometry, IMU for the whole sequence)\n", setup);
    std::printf("per frame       median %.2f ms, p90 %.2f ms, max %.2f ms\n",
                sorted[sorted.size() / 2], sorted[sorted.size() * 9 / 10], sorted.back());
    std::printf("render speed    %.1f frames/s (target >= 60; ratio %.2f)\n",
                1000.0 * frames / total, 1000.0 * frames / total / 60.0);
    return 0;
  });
}
