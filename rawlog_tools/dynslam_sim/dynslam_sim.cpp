// dynslam-sim: renders a synthetic dynamic scene (ini in params/sim/) into a rawlog with full
// ground truth. Same ini and seed -> byte-identical outputs.
#include "ContactSheet.h"
#include "SimulationWriter.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/core/ProgressReporter.h>
#include <dynslam/sim/MakeSequence.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>

namespace {
const char* kUsage =
    R"(usage: dynslam-sim --config params/sim/NAME.ini --out DIR [--set Section.key=value]...
                   [--contact-sheet FILE.png] [--sheet-frames N] [--quiet]
                   [--imu-gap START:SECONDS] [--black-frames FIRST:COUNT] [--no-depth FIRST:COUNT]
       dynslam-sim -h | --help

Renders the scenario of NAME.ini (sections [Scenario] [Camera] [People] [Cars] [Imu] [Gnss]
[Noise] [Augment] [Calibration], every key in docs/parameters.md; scene = room | corridor |
market | street, or augment: a real rawlog with movers inserted) into a rawlog with full ground
truth. The same ini and seed give byte-identical outputs.

Options:
  --config FILE.ini            the scenario
  --out DIR                    the output folder (created)
  --set Section.key=value      override one ini value (repeatable), e.g. --set
                               Scenario.duration=20; unknown keys and sections are errors
  --contact-sheet FILE.png     also write a PNG of frames spread over the sequence, one row
                               each: colour | depth | labels
  --sheet-frames N             rows of the contact sheet (default 4; first and last frame
                               included)
  --quiet                      no progress line on stderr
  --imu-gap START:SECONDS      drop the IMU samples from START s on for SECONDS (a sensor
                               fault, the ground truth unchanged: robustness tests)
  --black-frames FIRST:COUNT   write COUNT all-black colour images from frame FIRST on
  --no-depth FIRST:COUNT       write COUNT all-invalid (0) depth images from frame FIRST on
  -h, --help                   print this text and exit

Outputs in DIR (formats: docs/programs.md):
  sim.rawlog         CObservation3DRangeScan "RGBD" (depth uint16 mm, colour in sim_Images/),
                     CObservationIMU "IMU", CObservationGPS "GPS" (GGA, when [Gnss] enabled),
                     in time order
  groundtruth.tum    the camera's (optical frame) pose in the world per frame, TUM
  objects.txt        per frame and object in view: id, class, moving, world pose, amodal box,
                     visible pixels and fraction (the layout in its header)
  labels/NNNNNN.png  16-bit instance ids per pixel (0 = static scene)
  imu_biases.txt     the true gyro and accelerometer biases at each IMU sample
  calibration.txt    the true and the believed camera-IMU time offset and extrinsic
Exit codes: 0 written, 1 bad scenario or an output that cannot be written, 2 usage.
)";
/// --imu-gap, --black-frames, --no-depth: "FIRST:AMOUNT" pairs.
dynslam::rawlog_tools::SensorFaults readFaults(const dynslam::core::CommandLine& cl) {
  dynslam::rawlog_tools::SensorFaults faults;
  const auto pair = [&](const char* flag, auto& first, auto& second) {
    if (!cl.has(flag)) return;
    const std::string v = cl.valueOr(flag, "");
    const auto colon = v.find(':');
    try {
      if (colon == std::string::npos) throw std::invalid_argument("no colon");
      first = static_cast<std::decay_t<decltype(first)>>(std::stod(v.substr(0, colon)));
      second = static_cast<std::decay_t<decltype(second)>>(std::stod(v.substr(colon + 1)));
    } catch (const std::exception&) {
      throw dynslam::core::UsageError(std::string(flag) + " '" + v + "': expected FIRST:AMOUNT");
    }
  };
  pair("--imu-gap", faults.imu_gap_start, faults.imu_gap_duration);
  pair("--black-frames", faults.black_first, faults.black_count);
  pair("--no-depth", faults.no_depth_first, faults.no_depth_count);
  return faults;
}

/// The frames the contact sheet shows: N evenly spread, the first and the last included.
std::set<size_t> sheetRows(const dynslam::core::CommandLine& cl, size_t frames) {
  std::set<size_t> rows;
  const long long n = cl.optionalInteger("--sheet-frames").value_or(4);
  if (!cl.has("--contact-sheet")) return rows;
  for (long long r = 0; r < n; ++r)
    rows.insert(n == 1 ? 0 : static_cast<size_t>(std::lround(r * (frames - 1.0) / (n - 1))));
  return rows;
}

/// Renders every frame into `writer`, and the sheet's frames into `sheet`.
void renderAll(const dynslam::sim::Sequence& simulator,
               dynslam::rawlog_tools::SimulationWriter& writer, const std::set<size_t>& rows,
               dynslam::rawlog_tools::ContactSheet& sheet, bool quiet) {
  const size_t frames = simulator.frameCount();
  dynslam::core::ProgressReporter progress(stderr, !quiet && isatty(STDERR_FILENO), 5.0,
                                           "dynslam-sim");
  dynslam::sim::SimFrame frame;
  for (size_t i = 0; i < frames; ++i) {
    simulator.renderFrame(i, frame);
    writer.write(frame);
    if (rows.count(i)) {
      char caption[64];
      std::snprintf(caption, sizeof caption, "t = %.1f s, %zu objects", frame.t,
                    frame.objects.size());
      sheet.addRow(frame.image.rgb, frame.image.depth, frame.image.label, simulator.maxRange(),
                   caption);
    }
    if (!quiet) progress.update(i + 1, (i + 1.0) / frames);
  }
  writer.finish();
  if (!quiet) progress.finish(frames);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dynslam;
  return core::runProgram("dynslam-sim", [&] {
    core::CommandLine cl({"--config", "--out", "--contact-sheet", "--sheet-frames", "--imu-gap",
                          "--black-frames", "--no-depth"},
                         {"--quiet"}, {"--set"});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const auto cfg = core::IniConfig::fromFile(cl.required("--config"), cl.all("--set"));
    sim::ScenarioOptions options;
    options.load(cfg);
    const std::unique_ptr<sim::Sequence> sequence = sim::makeSequence(options);
    const sim::Sequence& simulator = *sequence;
    for (const auto& note : simulator.notes()) std::cerr << "dynslam-sim: " << note << "\n";
    rawlog_tools::SimulationWriter writer(cl.required("--out"), simulator, readFaults(cl),
                                          options.calibration);
    rawlog_tools::ContactSheet sheet;
    renderAll(simulator, writer, sheetRows(cl, simulator.frameCount()), sheet, cl.has("--quiet"));
    if (cl.has("--contact-sheet")) sheet.save(cl.valueOr("--contact-sheet", ""));
    std::cerr << "dynslam-sim: " << simulator.frameCount() << " frames, " << simulator.imu().size()
              << " IMU samples, " << simulator.gnss().size() << " GNSS fixes -> "
              << cl.required("--out") << "\n";
    return 0;
  });
}
