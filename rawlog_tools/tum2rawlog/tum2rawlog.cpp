// tum2rawlog: converts a TUM RGB-D sequence folder into an observations-only MRPT rawlog.
// Colour and depth are paired by nearest time stamp (TUM's associate.py rule); accelerometer
// samples become accelerometer-only IMU observations; everything is written in time order.
#include "TumSequence.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/OutputPaths.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/rawlog_tools/SensorLabels.h>
#include <dynslam/rawlog_tools/TimestampAssociation.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationIMU.h>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
using namespace dynslam::rawlog_tools;
using dynslam::core::CommandLine;

namespace {

constexpr const char* kUsage = R"(Usage: tum2rawlog --in DIR --out FILE.rawlog [options]
       tum2rawlog -h | --help

Converts a TUM RGB-D sequence folder (rgb.txt, depth.txt, rgb/, depth/, optional
accelerometer.txt and groundtruth.txt) into an MRPT rawlog of CObservation3DRangeScan
("RGBD", depth raw uint16 with rangeUnits = 1/5000 m) and accelerometer-only
CObservationIMU ("IMU") observations in time-stamp order. Each RGB-D observation carries
the colour frame's time stamp. groundtruth.txt is copied to <stem>.gt.tum beside FILE.

Options:
  --in DIR            sequence folder (its name picks freiburg1/2/3 intrinsics)
  --out FILE.rawlog   output rawlog; colour images go to <stem>_Images/ beside it
  --fx F --fy F --cx C --cy C
                      intrinsics (all four together) instead of the folder-name defaults
  --max-diff S        colour/depth association tolerance in seconds (default 0.02)
  --embed-images      store colour pixels inside the rawlog instead of <stem>_Images/
  -h, --help          print this text and exit

Outputs: FILE.rawlog, <stem>_Images/ (the colour images, as in the sequence), <stem>.gt.tum
(a copy of groundtruth.txt, when the folder has one). It prints the intrinsics used, the pairs
associated and dropped, and the observations written.
Exit codes: 0 written, 1 bad input (a missing or malformed list or image; no rawlog is left
behind), 2 usage.
)";

constexpr double kTumDepthUnits = 1.0 / 5000.0;

PinholeIntrinsics chooseIntrinsics(const CommandLine& args, const std::string& inDir) {
  const char* flags[] = {"--fx", "--fy", "--cx", "--cy"};
  const long given =
      std::count_if(std::begin(flags), std::end(flags), [&](const char* f) { return args.has(f); });
  if (given == 4) {
    std::cout << "intrinsics: from flags\n";
    return {*args.optionalDouble("--fx"), *args.optionalDouble("--fy"),
            *args.optionalDouble("--cx"), *args.optionalDouble("--cy")};
  }
  if (given != 0) throw ConversionError("--fx, --fy, --cx and --cy must be given together");
  // Only the folder's own name decides ("rgbd_dataset_freiburg1_xyz"), not its parents.
  fs::path folder = fs::absolute(inDir).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();
  const tum::NamedIntrinsics chosen = tum::intrinsicsForSequenceName(folder.filename().string());
  const PinholeIntrinsics& k = chosen.intrinsics;
  std::cout << "intrinsics: " << chosen.name << " (fx " << k.fx << ", fy " << k.fy << ", cx "
            << k.cx << ", cy " << k.cy << ")\n";
  return k;
}

// One thing to write: an associated colour/depth pair or an accelerometer sample.
struct Event {
  double t;
  bool isCamera;
  size_t index;  // into the association pairs or the accelerometer samples
};

/// The sequence's lists, read.
struct TumInput {
  std::vector<tum::ImageEntry> colour, depth;
  std::vector<tum::AccelerometerSample> acc;
};

/// Camera pairs and accelerometer samples in stamp order. Stable: at equal stamps cameras stay
/// before IMU samples, each in file order.
std::vector<Event> timeOrdered(const TumInput& in, const Association& association) {
  std::vector<Event> events;
  for (size_t i = 0; i < association.pairs.size(); ++i)
    events.push_back({in.colour[association.pairs[i].first].t, true, i});
  for (size_t i = 0; i < in.acc.size(); ++i) events.push_back({in.acc[i].t, false, i});
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });
  return events;
}

void writeEvent(const Event& event, const TumInput& in, const Association& association,
                const PinholeIntrinsics& intrinsics, ColourImageStore& images,
                RawlogWriter& writer) {
  if (!event.isCamera) {
    const auto& s = in.acc[event.index];
    writer.write(*makeImuObservation(mrpt::Clock::fromDouble(s.t), kImuLabel, std::nullopt, s.acc));
    return;
  }
  const auto& colour = in.colour[association.pairs[event.index].first];
  const auto& depth = in.depth[association.pairs[event.index].second];
  RgbdFrame frame;
  frame.timestamp = mrpt::Clock::fromDouble(colour.t);
  frame.sensorLabel = kRgbdLabel;
  frame.depthSourceName = depth.path;
  if (!fs::is_regular_file(depth.path))
    throw ConversionError("depth image " + depth.path + " does not exist");
  frame.depth = cv::imread(depth.path, cv::IMREAD_UNCHANGED);
  if (frame.depth.empty()) throw ConversionError("cannot read depth image " + depth.path);
  frame.rangeUnits = static_cast<float>(kTumDepthUnits);
  frame.intrinsics = intrinsics;
  frame.colour = images.storeFile(colour.path, fs::path(colour.path).stem().string());
  writer.write(*makeRgbdObservation(frame));
}

/// groundtruth.txt, when the folder has one, to <stem>.gt.tum.
void copyGroundTruth(const std::string& inDir, const RawlogOutputPaths& out) {
  const fs::path groundTruth = fs::path(inDir) / "groundtruth.txt";
  if (!fs::exists(groundTruth)) return;
  std::error_code ec;
  fs::copy_file(groundTruth, out.groundTruth, fs::copy_options::overwrite_existing, ec);
  if (ec) throw ConversionError("cannot copy " + groundTruth.string() + ": " + ec.message());
  std::cout << "ground truth: " << out.groundTruth << "\n";
}

int convert(const CommandLine& args) {
  const std::string inDir = args.required("--in");
  if (!fs::is_directory(inDir)) throw ConversionError("input folder " + inDir + " does not exist");
  const RawlogOutputPaths out = rawlogOutputPaths(args.required("--out"));
  const double maxDiff = args.optionalDouble("--max-diff").value_or(0.02);
  const PinholeIntrinsics intrinsics = chooseIntrinsics(args, inDir);

  TumInput in;
  in.colour = tum::readImageList(inDir, "rgb.txt");
  in.depth = tum::readImageList(inDir, "depth.txt");
  in.acc = tum::readAccelerometer((fs::path(inDir) / "accelerometer.txt").string());
  std::vector<double> colourStamps, depthStamps;
  for (const auto& e : in.colour) colourStamps.push_back(e.t);
  for (const auto& e : in.depth) depthStamps.push_back(e.t);
  const Association association = associateNearest(colourStamps, depthStamps, maxDiff);
  std::cout << "associated " << association.pairs.size() << " colour/depth pairs; dropped "
            << association.unmatchedFirst << " colour and " << association.unmatchedSecond
            << " depth frames without a partner within " << maxDiff << " s\n";

  ColourImageStore images(
      args.has("--embed-images") ? ImageStorage::Embedded : ImageStorage::External, out.imagesDir);
  RawlogWriter writer(out.rawlog);
  for (const Event& event : timeOrdered(in, association))
    writeEvent(event, in, association, intrinsics, images, writer);
  writer.close();
  copyGroundTruth(inDir, out);
  std::cout << "wrote " << writer.written() << " observations (" << association.pairs.size() << " "
            << kRgbdLabel << ", " << in.acc.size() << " " << kImuLabel << ") to " << out.rawlog
            << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("tum2rawlog", [&] {
    CommandLine args({"--in", "--out", "--fx", "--fy", "--cx", "--cy", "--max-diff"},
                     {"--embed-images"});
    args.parse(argc, argv);
    if (args.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return convert(args);
  });
}
