// dynslam-nav-demo: a robot driven by MRPT's reactive navigator through a list of goals among
// walking people, closed loop in the simulator (issue 54 items 2-3); writes its paths, the
// people's tracks, a top view and nav.json.
#include "nav_demo/ClosedLoop.h"
#include "nav_demo/NavReport.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>

#include <glog/logging.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

namespace {

using namespace dynslam;

const char* const kUsage = R"(usage: dynslam-nav-demo --config params/nav/NAME.ini --out DIR
                        [--obstacles estimated|ground_truth] [--set Section.key=value]...
                        [--no-video] [--quiet]

Drives a simulated differential-drive robot through the goals of NAME.ini with MRPT's
CReactiveNavigationSystem3D, sensing through dynslam's navigation adapter: with estimated
obstacles the SLAM system runs on the RGB-D frames and IMU samples rendered from where the robot
really is; with ground_truth the adapter gets the simulator's truth (the reference). The
scenario's people walk their paths and do not avoid the robot.
  --config INI       a navigation scenario ([NavDemo], [Robot], [Navigation]; params/nav/)
  --out DIR          output folder: nav.json, trajectory_true.tum, trajectory_estimated.tum,
                     people.csv, top.png, top.avi
  --obstacles WHAT   estimated | ground_truth (default: [NavDemo] obstacles)
  --set S.k=v        override a key (repeatable): sections NavDemo, Robot and Navigation of INI;
                     Scenario, Camera, People, Cars, Imu, Gnss, Noise, Calibration of the
                     scenario (e.g. Scenario.seed=3); any other of the SLAM ini
  --no-video         leave out top.avi
  --quiet            no progress lines
  -h, --help         print the usage and exit
Exit codes: 0 the run ended (whether or not every goal was reached: see nav.json), 1 bad input
or configuration, 2 usage.
)";

const std::set<std::string> kNavSections{"NavDemo", "Robot", "Navigation"};
const std::set<std::string> kScenarioSections{"Scenario", "Camera", "People", "Cars",
                                              "Imu",      "Gnss",   "Noise",  "Calibration"};

}  // namespace

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);  // Ceres's messages: errors only, to stderr
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_ERROR;
  return core::runProgram("dynslam-nav-demo", [&] {
    core::CommandLine cl({"--config", "--out", "--obstacles"}, {"--no-video", "--quiet"},
                         {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    std::vector<std::string> navSets, scenarioSets, slamSets;
    for (const auto& s : cl.all("--set")) {
      const std::string section = s.substr(0, s.find('.'));
      (kNavSections.count(section)        ? navSets
       : kScenarioSections.count(section) ? scenarioSets
                                          : slamSets)
          .push_back(s);
    }
    if (cl.has("--obstacles")) navSets.push_back("NavDemo.obstacles=" + cl.required("--obstacles"));
    const auto navIni = core::IniConfig::fromFile(cl.required("--config"), navSets);
    const navdemo::NavScenario scenario = navdemo::loadNavScenario(navIni);
    sim::ScenarioOptions world;
    world.load(core::IniConfig::fromFile(scenario.demo.scenario, scenarioSets));

    navdemo::ClosedLoopSettings settings;
    settings.out_dir = cl.required("--out");
    settings.slam_overrides = slamSets;
    settings.video = !cl.has("--no-video");
    const bool quiet = cl.has("--quiet");
    double lastPrint = -1e9;
    settings.progress = [&](double t, std::size_t goal) {
      if (quiet || t - lastPrint < 5.0) return;
      lastPrint = t;
      std::fprintf(stderr, "dynslam-nav-demo: t %.0f s, goal %zu of %zu\n", t,
                   std::min(goal + 1, scenario.goals.size()), scenario.goals.size());
    };
    const auto result = navdemo::runClosedLoop(scenario, world, settings);
    const std::string json = (std::filesystem::path(settings.out_dir) / "nav.json").string();
    navdemo::writeNavJson(json, scenario, world, result);
    navdemo::printSummary(std::cout, scenario, result);
    return 0;
  });
}
