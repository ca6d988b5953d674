// bench-objects: how far a planner can trust the object states a run wrote (issue 54 item 0).
// Scores RUN/objects/states.csv against the simulator's SIM/objects.txt, each state seen from the
// run's camera (RUN/trajectory.tum) and each body from the true one (SIM/groundtruth.tum): the
// rules are in object_scoring.h. Several --sim / --run pairs (in order) are scored each and
// pooled.
//
// Usage and flags: kUsage below (bench-objects --help).
#include "object_scoring.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/CommandLine.h>
#include <dynslam/core/JsonWriter.h>
#include <dynslam/core/Median.h>
#include <dynslam/core/TrajectoryFile.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace {

using namespace dynslam;

const char* const kUsage = R"(usage: bench-objects --sim DIR --run DIR [--sim DIR --run DIR ...]
                     [--gate M] [--min-visible F] [--json FILE] [--plot]

Scores each run's object states (RUN/objects/states.csv, written by dynslam with the
ObjectStates stage in [pipeline]) against its simulation (SIM/objects.txt, SIM/groundtruth.tum),
in the camera's frame on the ground plane, over every walking person in view.
  --sim DIR        a dynslam-sim output folder (repeat: paired with --run in order)
  --run DIR        the dynslam --out folder of a run on SIM/sim.rawlog
  --gate M         a state farther than M from a body is not paired with it (1.0)
  --min-visible F  a walking person counts as in view from this visible fraction (0.3)
  --json FILE      also write the pooled figures as JSON
  --plot           also draw each run's top view into RUN/objects_top.png
  -h, --help       print the usage and exit
Prints per run and pooled: position error (median, p90, m), velocity error (median, p90, m/s),
id switches, the share of in-view frames with a state, and the longest time a person in view
went without one (median and worst over persons, s).
)";

/// What is printed and written of a score, computed once.
struct Figures {
  double with_state_percent, position_median, position_p90, velocity_median, velocity_p90,
      gap_median, gap_max;
};

Figures figuresOf(const bench::ObjectScore& s) {
  return {s.scored ? 100.0 * s.paired / s.scored : 0.0,
          core::upperMedian(s.position_errors),
          core::upperPercentile(s.position_errors, 0.9),
          core::upperMedian(s.velocity_errors),
          core::upperPercentile(s.velocity_errors, 0.9),
          core::upperMedian(s.longest_gaps),
          s.longest_gaps.empty() ? 0.0
                                 : *std::max_element(s.longest_gaps.begin(), s.longest_gaps.end())};
}

void print(const char* what, const bench::ObjectScore& s) {
  const Figures f = figuresOf(s);
  std::printf(
      "%s: %d persons, %d frames in view, with a state %.1f %%; position error median %.3f p90 "
      "%.3f m; velocity error median %.3f p90 %.3f m/s; id switches %d; longest without a "
      "state median %.2f worst %.2f s\n",
      what, s.persons, s.scored, f.with_state_percent, f.position_median, f.position_p90,
      f.velocity_median, f.velocity_p90, s.id_switches, f.gap_median, f.gap_max);
}

/// Written whole or not at all, as every JSON the programs write.
void writeJson(const std::string& path, const bench::ObjectScore& s) {
  const Figures f = figuresOf(s);
  core::AtomicTextFile file(path);
  core::JsonWriter j(file.stream());
  j.beginObject()
      .member("persons", s.persons)
      .member("frames_in_view", s.scored)
      .member("frames_with_state", s.paired)
      .member("position_error_median_m", f.position_median)
      .member("position_error_p90_m", f.position_p90)
      .member("velocity_error_median_mps", f.velocity_median)
      .member("velocity_error_p90_mps", f.velocity_p90)
      .member("id_switches", s.id_switches)
      .member("longest_without_state_median_s", f.gap_median)
      .member("longest_without_state_max_s", f.gap_max)
      .endObject();
  file.stream() << "\n";
  file.commit();
}

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-objects", [&] {
    core::CommandLine cl({"--gate", "--min-visible", "--json"}, {"--plot"}, {"--sim", "--run"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const auto sims = cl.all("--sim"), runs = cl.all("--run");
    if (sims.empty() || sims.size() != runs.size())
      throw core::UsageError("give --sim and --run in pairs (" + std::to_string(sims.size()) +
                             " --sim, " + std::to_string(runs.size()) + " --run)");
    bench::ObjectScoringOptions options;
    options.gate_m = cl.optionalDouble("--gate").value_or(options.gate_m);
    options.min_visible = cl.optionalDouble("--min-visible").value_or(options.min_visible);
    bench::ObjectScore pooled;
    for (std::size_t k = 0; k < sims.size(); ++k) {
      const auto truth = core::readObjectGroundTruth(sims[k] + "/objects.txt");
      const auto trueCamera = core::readTum(sims[k] + "/groundtruth.tum");
      const auto estimatedCamera = core::readTum(runs[k] + "/trajectory.tum");
      const auto states = bench::readObjectStates(runs[k] + "/objects/states.csv");
      const auto score =
          bench::scoreObjectStates(truth, trueCamera, estimatedCamera, states, options);
      if (cl.has("--plot"))
        bench::writeTopView(runs[k] + "/objects_top.png", truth, trueCamera, estimatedCamera,
                            states, options);
      print(runs[k].c_str(), score);
      bench::pool(pooled, score);
    }
    if (sims.size() > 1) print("pooled", pooled);
    if (cl.has("--json")) writeJson(cl.required("--json"), pooled);
    return 0;
  });
}
