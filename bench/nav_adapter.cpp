// bench-nav-adapter: how long the navigation adapter's two calls take while the SLAM system runs
// (issue 54 item 1). A rawlog is replayed into a System on its own processing thread, as a live
// robot's would be, while a navigation thread calls getCurrentPoseAndSpeeds and senseObstacles
// at a fixed rate, as CReactiveNavigationSystem3D's navigationStep does.
//
// Usage and flags: kUsage below (bench-nav-adapter --help).
#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Median.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/nav/NavigationAdapter.h>
#include <dynslam/nav/SystemEstimateSource.h>
#include <dynslam/system/System.h>

#include <mrpt/maps/CSimplePointsMap.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

namespace {

using namespace dynslam;
using Clock = std::chrono::steady_clock;

const char* const kUsage = R"(usage: bench-nav-adapter --rawlog FILE --config INI [--set S.k=v]...
                         [--nav-config INI] [--nav-set Navigation.k=v]... [--rate HZ]
                         [--json FILE]

Replays FILE into a dynslam System configured by INI (its own processing thread) while a second
thread calls the navigation adapter's getCurrentPoseAndSpeeds and senseObstacles at HZ.
  --rawlog FILE     the recording (e.g. a dynslam-sim output's sim.rawlog)
  --config INI      the SLAM configuration (e.g. params/sim_vio.ini)
  --set S.k=v       override a key of INI (repeatable)
  --nav-config INI  the adapter's [Navigation] section (default: its defaults)
  --nav-set Navigation.k=v  override a [Navigation] key (repeatable)
  --rate HZ         calls per second of each kind (20)
  --json FILE       also write the figures as JSON
  -h, --help        print the usage and exit
Prints for each call: calls, answers, median, p99 and max wall time (microseconds); the
obstacles handed over (median, max points) and the frames the system processed meanwhile.
)";

struct CallTimes {
  std::vector<double> us;
  int answered = 0;
  void add(Clock::duration d, bool ok) {
    us.push_back(std::chrono::duration<double, std::micro>(d).count());
    answered += ok;
  }
};

void print(const char* what, const CallTimes& c) {
  std::printf("%s: %zu calls, %d answered; median %.1f us, p99 %.1f us, max %.1f us\n", what,
              c.us.size(), c.answered, core::upperMedian(c.us), core::upperPercentile(c.us, 0.99),
              c.us.empty() ? 0.0 : *std::max_element(c.us.begin(), c.us.end()));
}

void member(core::JsonWriter& j, const std::string& name, const CallTimes& c) {
  j.key(name)
      .beginObject()
      .member("calls", static_cast<long long>(c.us.size()))
      .member("answered", c.answered)
      .member("median_us", core::upperMedian(c.us))
      .member("p99_us", core::upperPercentile(c.us, 0.99))
      .member("max_us", c.us.empty() ? 0.0 : *std::max_element(c.us.begin(), c.us.end()))
      .endObject();
}

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-nav-adapter", [&] {
    core::CommandLine cl({"--rawlog", "--config", "--nav-config", "--rate", "--json"}, {},
                         {"--set", "--nav-set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const double rate = cl.optionalDouble("--rate").value_or(20.0);
    if (!(rate > 0)) throw core::UsageError("--rate must be above 0");
    nav::NavigationOptions options;
    core::IniConfig navIni = cl.has("--nav-config")
                                 ? core::IniConfig::fromFile(cl.required("--nav-config"))
                                 : core::IniConfig::fromText("", "<defaults>");
    for (const auto& assignment : cl.all("--nav-set")) navIni.applyOverride(assignment);
    core::rejectUnknownSections(navIni, {nav::NavigationOptions::kSection});
    core::loadOptionsStrict(options, navIni, nav::NavigationOptions::kSection);

    system::System slam(cl.required("--config"), cl.all("--set"));
    nav::SystemEstimateSource source(slam);
    nav::NavigationAdapter adapter(source, options);
    io::RawlogSource rawlog(
        cl.required("--rawlog"),
        static_cast<std::size_t>(slam.sensorSync().max_observation_mb * (1 << 20)));

    std::atomic<bool> done{false};
    CallTimes poseCalls, obstacleCalls;
    std::vector<double> obstacleCounts;
    std::thread navigation([&] {
      mrpt::maps::CSimplePointsMap obstacles;
      mrpt::math::TPose2D pose, odometry;
      mrpt::math::TTwist2D velocity;
      mrpt::system::TTimeStamp stamp;
      std::string frame;
      const auto period =
          std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / rate));
      for (auto next = Clock::now(); !done; next += period) {
        std::this_thread::sleep_until(next);
        auto t0 = Clock::now();
        const bool posed = adapter.getCurrentPoseAndSpeeds(pose, velocity, stamp, odometry, frame);
        poseCalls.add(Clock::now() - t0, posed);
        t0 = Clock::now();
        const bool sensed = adapter.senseObstacles(obstacles, stamp);
        obstacleCalls.add(Clock::now() - t0, sensed);
        if (sensed) obstacleCounts.push_back(static_cast<double>(obstacles.size()));
      }
    });
    try {
      while (auto observation = rawlog.next()) slam.onNewObservation(observation);
      slam.flush();
    } catch (...) {
      done = true;
      navigation.join();
      throw;
    }
    done = true;
    navigation.join();

    std::printf("rawlog %s, %zu frames processed, [Navigation] obstacle_horizon_s %.2f\n",
                cl.required("--rawlog").c_str(), slam.framesProcessed(),
                options.obstacle_horizon_s);
    print("getCurrentPoseAndSpeeds", poseCalls);
    print("senseObstacles", obstacleCalls);
    std::printf(
        "obstacle points per answer: median %.0f, max %.0f\n", core::upperMedian(obstacleCounts),
        obstacleCounts.empty() ? 0.0
                               : *std::max_element(obstacleCounts.begin(), obstacleCounts.end()));
    if (cl.has("--json")) {
      core::AtomicTextFile file(cl.required("--json"));
      core::JsonWriter j(file.stream());
      j.beginObject().member("frames", static_cast<long long>(slam.framesProcessed()));
      member(j, "getCurrentPoseAndSpeeds", poseCalls);
      member(j, "senseObstacles", obstacleCalls);
      j.member("obstacle_points_median", core::upperMedian(obstacleCounts)).endObject();
      file.stream() << "\n";
      file.commit();
    }
    return 0;
  });
}
