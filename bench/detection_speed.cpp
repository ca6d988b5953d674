// Detector latency on real pedestrian video (issue 4: YOLOX-nano latency at input 416 and 320,
// HOG for comparison) and the rate the real-time detector thread sustains while the rest of the
// pipeline keeps a core busy. Frames: vtest.avi (opencv-doc) resized to 640x480, the system's
// image size, sampled evenly. YOLOX runs as configured by default (trim_padding: a 416 x 320
// network input for these 4:3 frames); the "square" rows letterbox into 416 x 416, as a model
// with a fixed square input needs.
//
//   build/bin/bench-detection [--frames 50] [--model ../shared/models/yolox_nano.onnx]
//                             [--video /usr/share/doc/opencv-doc/examples/data/vtest.avi]
//                             [--realtime-seconds 4]
#include "detection_accuracy.h"

#include <dynslam/core/CommandLine.h>
#include <dynslam/detection/HogPeopleDetector.h>
#include <dynslam/detection/OnnxYoloDetector.h>
#include <dynslam/detection/RealtimeDetector.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>
#include <vector>

namespace {

using namespace dynslam;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::vector<core::Frame> sampleFrames(const std::string& video_path, int count) {
  cv::VideoCapture video(video_path);
  if (!video.isOpened()) throw std::runtime_error("cannot open the video '" + video_path + "'");
  const int total = static_cast<int>(video.get(cv::CAP_PROP_FRAME_COUNT));
  std::vector<core::Frame> frames;
  for (int i = 0; i < count; ++i) {
    video.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(i) * total / count);
    cv::Mat image;
    if (!video.read(image)) break;
    core::Frame frame;
    frame.index =
        static_cast<std::size_t>(i) * static_cast<std::size_t>(total) /
        static_cast<std::size_t>(count);  // the video's frame (objects.txt's with --truth)
    frame.t = i / 30.0;
    cv::resize(image, frame.rgb, cv::Size(640, 480), 0, 0, cv::INTER_AREA);
    frames.push_back(frame);
  }
  if (frames.empty()) throw std::runtime_error("no frame decoded from '" + video_path + "'");
  return frames;
}

/// Median and 90th percentile latency and mean detections per frame of one detector.
void benchLatency(const char* name, detection::Detector& detector,
                  const std::vector<core::Frame>& frames) {
  for (int i = 0; i < 3; ++i) detector.detect(frames[static_cast<std::size_t>(i) % frames.size()]);
  std::vector<double> ms;
  std::size_t people = 0, all = 0;
  for (const auto& frame : frames) {
    const auto start = Clock::now();
    const auto found = detector.detect(frame);
    ms.push_back(msSince(start));
    all += found.size();
    for (const auto& d : found) people += d.category == "person";
  }
  std::sort(ms.begin(), ms.end());
  const double n = static_cast<double>(frames.size());
  std::printf("%-34s %8.1f %8.1f %9.1f %9.2f %9.2f\n", name, ms[ms.size() / 2],
              ms[ms.size() * 9 / 10], 1000.0 / ms[ms.size() / 2], people / n, all / n);
}

/// Frames handed to a RealtimeDetector at 30 Hz while this thread spins busy for `rest_ms` of
/// each frame period, as the rest of a pipeline would (33 ms: a core fully loaded); returns the
/// detector's results per second.
double realtimeRate(std::unique_ptr<detection::Detector> detector,
                    const std::vector<core::Frame>& frames, double seconds, double rest_ms) {
  detection::RealtimeDetector realtime(std::move(detector));
  const auto start = Clock::now();
  std::size_t delivered = 0, i = 0;
  volatile double sink = 0;
  while (msSince(start) < 1000.0 * seconds) {
    const auto frame_start = Clock::now();
    core::Frame frame = frames[i++ % frames.size()];
    if (realtime.poll()) ++delivered;
    realtime.submit(frame);
    while (msSince(frame_start) < rest_ms) sink = sink + 1.0;  // "the rest of the pipeline"
    const double idle_ms = 1000.0 / 30.0 - msSince(frame_start);
    if (idle_ms > 0)
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(idle_ms));
  }
  return delivered / (msSince(start) / 1000.0);
}

/// --truth: recall and precision of YOLOX-nano (416, 320) and HOG on the sampled frames.
void printAccuracy(const core::CommandLine& cl, const std::vector<core::Frame>& frames,
                   std::unique_ptr<detection::Detector> yolo416,
                   std::unique_ptr<detection::Detector> yolo320) {
  const double minVisible = cl.optionalDouble("--min-visible").value_or(0.5);
  const auto truth = bench::readTruePeople(cl.required("--truth"), minVisible);
  std::printf("\naccuracy against %s: people at least %.2f visible, box IoU >= 0.5\n",
              cl.required("--truth").c_str(), minVisible);
  std::printf("%-34s %8s %9s %8s %8s %8s\n", "detector", "recall", "precision", "found", "missed",
              "false+");
  detection::HogPeopleDetector hog({}, detection::ClassMap());
  const std::pair<const char*, detection::Detector*> detectors[] = {
      {"yolox_nano input 416", yolo416.get()},
      {"yolox_nano input 320", yolo320.get()},
      {"hog people (min_height 128)", &hog}};
  const std::string drawDir = cl.valueOr("--draw", "");
  if (!drawDir.empty()) std::filesystem::create_directories(drawDir);
  for (const auto& [name, detector] : detectors) {
    const bench::DetectionScore s = bench::scoreDetector(
        *detector, frames, truth, detector == yolo416.get() ? drawDir : std::string());
    std::printf("%-34s %8.3f %9.3f %8zu %8zu %8zu\n", name, s.recall(), s.precision(), s.found,
                s.missed, s.false_positives);
  }
}

const char* const kUsage =
    R"(usage: bench-detection [--frames N] [--model FILE.onnx] [--video FILE] [--realtime-seconds S]
                       [--truth objects.txt [--min-visible F] [--draw DIR]]
       bench-detection -h | --help

Detector latency on real pedestrian video: YOLOX-nano at network inputs 416 and 320 (trimmed
to the frame's 4:3 shape, and square), on all threads and on one, and OpenCV's HOG people
detector, as median / p90 ms and Hz with people and detections per frame; then the rate the
real-time detector thread sustains while a pipeline thread feeds 30 Hz frames and works 10 or
33 ms of each period. Frames: the video resized to 640x480, sampled evenly.

Options:
  --frames N             frames sampled from the video (default 50)
  --model FILE.onnx      the YOLOX-nano model (default ../shared/models/yolox_nano.onnx)
  --video FILE           the video (default
                         /usr/share/doc/opencv-doc/examples/data/vtest.avi, package opencv-doc)
  --realtime-seconds S   seconds of each real-time measurement (default 4)
  --truth objects.txt    also score the detectors against a simulated sequence's ground truth
                         (--video DIR/sim_Images/colour_%06d.png of the same dynslam-sim output):
                         person boxes matched one to one at IoU >= 0.5 with the true amodal boxes;
                         recall over the people at least --min-visible visible, precision over
                         every detection (one on a less visible person counts neither way)
  --min-visible F        the visible share from which a person must be found (default 0.5)
  --draw DIR             with --truth: write each scored frame with YOLOX-nano (416)'s boxes to
                         DIR/detections_NNNNNN.png (green: a person to find, grey: less visible,
                         blue: a detection matched, red: a false positive)
  -h, --help             print this text and exit

Exit codes: 0 done, 1 the model or the video cannot be read, 2 usage.
)";

}  // namespace

int main(int argc, char** argv) {
  return core::runProgram("bench-detection", [&] {
    core::CommandLine cl({"--frames", "--model", "--video", "--realtime-seconds", "--truth",
                          "--min-visible", "--draw"},
                         {});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    const int count = static_cast<int>(cl.optionalInteger("--frames").value_or(50));
    const std::string model = cl.valueOr("--model", "../shared/models/yolox_nano.onnx");
    const double rt_seconds = cl.optionalDouble("--realtime-seconds").value_or(4.0);
    const auto frames = sampleFrames(
        cl.valueOr("--video", "/usr/share/doc/opencv-doc/examples/data/vtest.avi"), count);
    std::printf("%zu vtest.avi frames at 640x480; OpenCV %s, %d threads by default\n\n",
                frames.size(), CV_VERSION, cv::getNumThreads());
    std::printf("%-34s %8s %8s %9s %9s %9s\n", "detector", "median", "p90", "Hz", "people", "all");
    std::printf("%-34s %8s %8s %9s %9s %9s\n", "", "ms", "ms", "(median)", "/frame", "/frame");

    const auto yolo = [&](int input, int threads, bool trim = true) {
      detection::OnnxYoloDetectorSettings s;
      s.model = model;
      s.input_size = input;
      s.threads = threads;
      s.trim_padding = trim;
      return std::make_unique<detection::OnnxYoloDetector>(s, detection::ClassMap());
    };
    benchLatency("yolox_nano input 416", *yolo(416, 0), frames);
    benchLatency("yolox_nano input 320", *yolo(320, 0), frames);
    benchLatency("yolox_nano input 416 square", *yolo(416, 0, false), frames);
    benchLatency("yolox_nano input 320 square", *yolo(320, 0, false), frames);
    detection::HogPeopleDetector hog({}, detection::ClassMap());
    benchLatency("hog people (min_height 128)", hog, frames);
    const int default_threads = cv::getNumThreads();
    benchLatency("yolox_nano input 416, 1 thread", *yolo(416, 1), frames);
    benchLatency("yolox_nano input 320, 1 thread", *yolo(320, 1), frames);
    cv::setNumThreads(default_threads);
    if (cl.has("--truth")) printAccuracy(cl, frames, yolo(416, 0), yolo(320, 0));

    std::printf(
        "\nreal-time mode: detections/s the detector thread delivers while the pipeline thread "
        "feeds 30 Hz frames and works `rest` ms of each 33 ms period (%.0f s each; target >= 15)\n",
        rt_seconds);
    std::printf("%-34s %12s %12s\n", "detector", "rest 10 ms", "rest 33 ms");
    for (const int input : {416, 320})
      for (const int threads : {0, 1}) {
        double hz[2];
        for (int k = 0; k < 2; ++k) {
          hz[k] = realtimeRate(yolo(input, threads), frames, rt_seconds, k == 0 ? 10.0 : 34.0);
          cv::setNumThreads(default_threads);
        }
        char name[64];
        std::snprintf(name, sizeof name, "yolox_nano input %d, %d thread%s", input,
                      threads ? threads : default_threads, threads == 1 ? "" : "s");
        std::printf("%-34s %12.1f %12.1f\n", name, hz[0], hz[1]);
      }
    return 0;
  });
}
