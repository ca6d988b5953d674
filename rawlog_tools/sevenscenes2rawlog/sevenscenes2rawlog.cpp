// sevenscenes2rawlog: converts a 7-Scenes sequence folder into an observations-only MRPT
// rawlog of RGB-D observations, plus its ground truth as TUM.
#include "SevenScenesFolder.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/ConversionError.h>
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/OutputPaths.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/rawlog_tools/SensorLabels.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace dynslam::rawlog_tools;
using dynslam::core::CommandLine;

namespace {

constexpr const char* kUsage = R"(Usage: sevenscenes2rawlog --in DIR --out FILE.rawlog [options]
       sevenscenes2rawlog -h | --help

Converts a Microsoft 7-Scenes sequence folder (frame-NNNNNN.color.jpg / .depth.png /
.pose.txt, camera-intrinsics.txt) into an MRPT rawlog of CObservation3DRangeScan ("RGBD")
observations: depth raw uint16 millimetres (rangeUnits = 1/1000; 65535 = invalid becomes 0)
with the intrinsics of camera-intrinsics.txt (the depth camera's, f = 585 px), colour with the
colour camera's (f = 525 px, the same principal point; --colour-intrinsics), the two cameras at
the same place: readers register the depth to the colour image. The camera-to-world poses are
written as TUM to <stem>.gt.tum beside FILE, with the frames' time stamps.

7-Scenes has no time stamps: frame N gets t0 + N/30 s (30 Hz), whatever --first is, so the
same frame has the same stamp in every converted range. The default t0 is the fixed Unix time
1600000000 (2020-09-13 12:26:40 UTC), not 0: MRPT reads a time of 0.0 as "no time stamp"
(Clock::toDouble gives 0 for invalid stamps; rawlog-edit --info skips such a frame).

Options:
  --in DIR            sequence folder
  --out FILE.rawlog   output rawlog; colour images go to <stem>_Images/ beside it
  --first N           first frame number (default 0)
  --last M            last frame number, inclusive (default: the last frame in DIR)
  --t0 SECONDS        time stamp of frame 0 (default 1600000000; must be > 0)
  --colour-intrinsics fx,fy,cx,cy | depth
                      the colour camera's intrinsics (default 525,525 and the principal point
                      of camera-intrinsics.txt); depth: the depth camera's (colour and depth
                      taken as registered, which 7-Scenes' are not)
  --embed-images      store colour pixels inside the rawlog instead of <stem>_Images/
  -h, --help          print this text and exit

Outputs: FILE.rawlog, <stem>_Images/ (the colour JPEGs, byte for byte), <stem>.gt.tum (the
frames' camera-to-world poses, TUM). It prints the frames and intrinsics written.
Exit codes: 0 written, 1 bad input (a missing frame, pose or intrinsics file; a range outside
the folder), 2 usage.
)";

/// "fx,fy,cx,cy" (pixels, all finite, focal lengths > 0).
PinholeIntrinsics parseIntrinsics(const std::string& flag, const std::string& text) {
  std::vector<double> v;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) v.back() = std::nan("");
    } catch (const std::exception&) {
      v.push_back(std::nan(""));
    }
  }
  const bool ok = v.size() == 4 && std::isfinite(v[0]) && std::isfinite(v[1]) &&
                  std::isfinite(v[2]) && std::isfinite(v[3]) && v[0] > 0 && v[1] > 0;
  if (!ok)
    throw ConversionError(flag + " '" + text + "': expected fx,fy,cx,cy in pixels (fx, fy > 0)");
  return {v[0], v[1], v[2], v[3]};
}

constexpr double kFrameRate = 30.0;
/// 7-Scenes' colour camera (the relocalization literature's value, e.g. DSAC*); the 585 px of
/// camera-intrinsics.txt belong to its depth camera. On the shared 600 frames, RGB-D only
/// (params/7scenes_vo.ini): APE 0.0431 m with 585 (trajectory scale 1.060 short), 0.0277 with
/// 525 (0.988); 515 / 535 give 0.0300 / 0.0251 (README "Estimator").
constexpr double kColourFocal = 525.0;
constexpr double kDefaultT0 = 1600000000.0;
constexpr uint16_t kInvalidDepth = 65535;

/// --first and --last, checked against the folder before anything is converted, so a range
/// typo fails at once, not after minutes.
std::pair<long long, long long> frameRange(const CommandLine& args, const std::string& inDir) {
  const long long first = args.optionalInteger("--first").value_or(0);
  const long long lastInDir = sevenscenes::lastFrameIndex(inDir);
  const long long last = args.has("--last") ? *args.optionalInteger("--last") : lastInDir;
  if (first < 0) throw ConversionError("--first must be >= 0");
  if (last < first)
    throw ConversionError("no frames to convert: --first " + std::to_string(first) +
                          " is after the last frame " + std::to_string(last));
  if (last > lastInDir)
    throw ConversionError(sevenscenes::framePaths(inDir, last).colour + " does not exist (the " +
                          "last frame in " + inDir + " is " + std::to_string(lastInDir) + ")");
  return {first, last};
}

/// The colour camera's intrinsics: 525 px and the depth camera's principal point by default,
/// --colour-intrinsics fx,fy,cx,cy, or none (registered to depth) with --colour-intrinsics depth.
std::optional<PinholeIntrinsics> colourIntrinsicsOf(const CommandLine& args,
                                                    const PinholeIntrinsics& depth) {
  std::optional<PinholeIntrinsics> colour =
      PinholeIntrinsics{kColourFocal, kColourFocal, depth.cx, depth.cy};
  const std::string text = args.valueOr("--colour-intrinsics", "");
  if (text == "depth")
    colour.reset();
  else if (!text.empty())
    colour = parseIntrinsics("--colour-intrinsics", text);
  return colour;
}

RgbdFrame readFrame(const sevenscenes::FramePaths& paths, double t,
                    const PinholeIntrinsics& intrinsics,
                    const std::optional<PinholeIntrinsics>& colourIntrinsics,
                    ColourImageStore& images) {
  RgbdFrame frame;
  frame.timestamp = mrpt::Clock::fromDouble(t);
  frame.sensorLabel = kRgbdLabel;
  frame.depthSourceName = paths.depth;
  if (!fs::is_regular_file(paths.depth))
    throw ConversionError("depth image " + paths.depth + " does not exist");
  frame.depth = cv::imread(paths.depth, cv::IMREAD_UNCHANGED);
  if (frame.depth.empty()) throw ConversionError("cannot read depth image " + paths.depth);
  frame.invalidDepthValue = kInvalidDepth;
  frame.rangeUnits = 1.0f / 1000.0f;
  frame.intrinsics = intrinsics;
  frame.colourIntrinsics = colourIntrinsics;
  frame.colour = images.storeFile(paths.colour, fs::path(paths.colour).stem().string());
  return frame;
}

int convert(const CommandLine& args) {
  const std::string inDir = args.required("--in");
  if (!fs::is_directory(inDir)) throw ConversionError("input folder " + inDir + " does not exist");
  const RawlogOutputPaths out = rawlogOutputPaths(args.required("--out"));
  const double t0 = args.optionalDouble("--t0").value_or(kDefaultT0);
  if (t0 <= 0) throw ConversionError("--t0 must be > 0 (MRPT reads time 0 as 'no time stamp')");
  const auto [first, last] = frameRange(args, inDir);
  const PinholeIntrinsics intrinsics = sevenscenes::readIntrinsics(inDir);
  // camera-intrinsics.txt is the depth camera's; the colour camera is wider (see kUsage).
  const std::optional<PinholeIntrinsics> colourIntrinsics = colourIntrinsicsOf(args, intrinsics);
  const PinholeIntrinsics colour = colourIntrinsics.value_or(intrinsics);

  ColourImageStore images(
      args.has("--embed-images") ? ImageStorage::Embedded : ImageStorage::External, out.imagesDir);
  RawlogWriter writer(out.rawlog);
  dynslam::core::Trajectory groundTruth;
  for (long long index = first; index <= last; ++index) {
    const sevenscenes::FramePaths paths = sevenscenes::framePaths(inDir, index);
    const double t = t0 + static_cast<double>(index) / kFrameRate;
    const RgbdFrame frame = readFrame(paths, t, intrinsics, colourIntrinsics, images);
    groundTruth.push_back({t, sevenscenes::readPose(paths.pose)});
    writer.write(*makeRgbdObservation(frame));
  }
  writer.close();
  dynslam::core::writeTum(out.groundTruth, groundTruth);

  std::cout << "wrote " << writer.written() << " " << kRgbdLabel << " observations (frames "
            << first << ".." << last << ", depth intrinsics fx " << intrinsics.fx << " fy "
            << intrinsics.fy << " cx " << intrinsics.cx << " cy " << intrinsics.cy << ", colour fx "
            << colour.fx << " fy " << colour.fy << " cx " << colour.cx << " cy " << colour.cy
            << ") to " << out.rawlog << "\nground truth: " << out.groundTruth << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("sevenscenes2rawlog", [&] {
    CommandLine args({"--in", "--out", "--first", "--last", "--t0", "--colour-intrinsics"},
                     {"--embed-images"});
    args.parse(argc, argv);
    if (args.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return convert(args);
  });
}
