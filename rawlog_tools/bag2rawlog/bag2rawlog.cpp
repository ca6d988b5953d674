// bag2rawlog: converts a ROS 1 bag (OpenLORIS-Scene, RealSense D4xx recordings) into an
// observations-only MRPT rawlog; a small ini says which topic becomes which observation.
#include "BagConverter.h"
#include "TopicMap.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/core/Config.h>
#include <dynslam/rawlog_tools/ColourImageStore.h>
#include <dynslam/rawlog_tools/OutputPaths.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>

#include <cstdio>
#include <iostream>

using namespace dynslam::rawlog_tools;
using dynslam::core::CommandLine;

namespace {

constexpr const char* kUsage =
    R"(Usage: bag2rawlog --bag FILE.bag --topics TOPICS.ini --out FILE.rawlog [options]
       bag2rawlog --print-topics-template
       bag2rawlog -h | --help

Converts a ROS 1 bag into an MRPT rawlog, written in header-stamp order:
  rgb_topic + depth_topic -> CObservation3DRangeScan "RGBD" (each colour image with the nearest
      depth image within rgbd_max_dt; depth 16UC1/mono16 raw with rangeUnits = depth_unit,
      32FC1 metres stored as millimetres; intrinsics from camera_info_topic or fx fy cx cy)
  imu_topic, or accel_topic + gyro_topic -> CObservationIMU "IMU" (split RealSense streams:
      one sample per gyro message, accelerometer interpolated at its stamp)
  gnss_topic (NavSatFix) -> CObservationGPS "GPS" with an NMEA GGA message
  nmea_topic (nmea_msgs/Sentence) -> CObservationGPS "GPS" as MRPT's NMEA parser reads it
Colour images go to <stem>_Images/ beside the rawlog (compressed images byte for byte, raw
images as PNG). Example topic maps: params/bag2rawlog/*.ini; every key is listed with
--print-topics-template.

Options:
  --bag FILE.bag         input bag
  --topics FILE.ini      topic map, section [bag2rawlog] (unknown keys are errors)
  --set bag2rawlog.key=value   override a topic-map key (repeatable)
  --out FILE.rawlog      output rawlog
  --embed-images         store colour pixels inside the rawlog instead of <stem>_Images/
  --print-topics-template  print every topic-map key with its default and meaning, then exit
  -h, --help             print this text and exit

Outputs: FILE.rawlog, <stem>_Images/ beside it (unless --embed-images). It prints the messages
read and the observations written per sensor label, and warns (stderr) of what it left out:
colour without depth, unpaired depth, gyro samples outside the accelerometer's span, samples
out of order, NavSatFix without a fix, NMEA sentences MRPT does not read, observations later
than reorder_window.
Exit codes: 0 written, 1 bad input (missing bag, a mapped topic the bag lacks or of the wrong
type, an inconsistent topic map, an unreadable depth encoding) or no observation written,
2 usage.
)";

int run(const CommandLine& args) {
  if (args.has("--print-topics-template")) {
    bag::TopicMap defaults;
    defaults.dumpToConsole();
    return 0;
  }
  const std::string topicsFile = args.required("--topics");
  const auto cfg = dynslam::core::IniConfig::fromFile(topicsFile, args.all("--set"));
  dynslam::core::rejectUnknownSections(cfg, {bag::kSection});
  bag::TopicMap topics;
  dynslam::core::loadOptionsStrict(topics, cfg, bag::kSection);
  topics.validate(topicsFile);
  const std::string bagFile = args.required("--bag");
  const RawlogOutputPaths out = rawlogOutputPaths(args.required("--out"));

  ColourImageStore images(
      args.has("--embed-images") ? ImageStorage::Embedded : ImageStorage::External, out.imagesDir);
  RawlogWriter writer(out.rawlog);
  const bag::ConversionSummary s =
      bag::convertBag(bagFile, topics, topicsFile, images, writer, stderr);
  writer.close();

  std::cout << "read " << s.messages << " messages from " << bagFile << "; wrote "
            << writer.written() << " observations to " << out.rawlog << ":";
  for (const auto& [label, count] : writer.writtenPerLabel())
    std::cout << " " << label << " " << count;
  std::cout << "\n";
  auto note = [](size_t n, const char* what) {
    if (n) std::cerr << "bag2rawlog: warning: " << n << " " << what << "\n";
  };
  note(s.unmatchedColour, "colour images had no depth image within rgbd_max_dt (not written)");
  note(s.unmatchedDepth, "depth images were not paired with a colour image");
  note(s.droppedGyro, "gyro samples lay outside the accelerometer's time span (not written)");
  note(s.outOfOrderImu, "accel/gyro samples did not increase in stamp (not written)");
  note(s.gnssWithoutFix, "NavSatFix messages had no fix (not written)");
  note(s.nmeaSkipped, "NMEA sentences were not recognised by MRPT's parser (not written)");
  note(s.late, "observations came later than reorder_window (not written; raise it)");
  if (writer.written() == 0) {
    std::cerr << "bag2rawlog: error: no observation was written\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("bag2rawlog", [&] {
    CommandLine args({"--bag", "--topics", "--out", "--set"},
                     {"--embed-images", "--print-topics-template"}, {"--set"});
    args.parse(argc, argv);
    if (args.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    return run(args);
  });
}
