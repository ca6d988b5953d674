// The Detection stage: created by name, configured from [Detection] (only the chosen detector's
// keys are valid), fills the frame inline or from the detector thread.
#include <dynslam/core/StageRegistry.h>
#include <dynslam/detection/DetectionStage.h>
#include <dynslam/detection/RegisterStages.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <thread>

namespace det = dynslam::detection;
namespace dt = dynslam::testing;
using dynslam::core::ConfigError;
using dynslam::core::IniConfig;

namespace {

/// objects.txt with one person on every frame of a 30 Hz sequence from t = 100 s.
std::string writeObjects(int frames) {
  std::ostringstream out;
  out.precision(17);
  for (int f = 0; f < frames; ++f)
    out << f << ' ' << 100.0 + f / 30.0 << " 5 person 1 0 0 0 0 0 0 1 " << 10 + f
        << " 20 30 60 900 1\n";
  return dt::writeTextFile(dt::scratchDir() + "/objects.txt", out.str());
}

dynslam::core::Frame frameAt(int f) {
  dynslam::core::Frame frame;
  frame.index = static_cast<std::size_t>(f);
  frame.t = 100.0 + f / 30.0;
  frame.rgb = cv::Mat(120, 160, CV_8UC3, cv::Scalar::all(0));
  return frame;
}

std::string configError(const std::string& ini) {
  det::DetectionStage stage;
  try {
    stage.configure(IniConfig::fromText(ini, "test.ini"), "Detection");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DetectionStage, IsRegisteredAsDetection) {
  dynslam::core::StageRegistry registry;
  det::registerStages(registry);
  ASSERT_TRUE(registry.contains("Detection"));
  EXPECT_NE(dynamic_cast<det::DetectionStage*>(registry.create("Detection").get()), nullptr);
}

TEST(DetectionStage, ConfigErrorsNameSectionKeyAndPath) {
  EXPECT_NE(configError("[Detection]\ndetector = yolo\n").find("detector = 'yolo'"),
            std::string::npos);
  // A key of another detector is unknown, not silently ignored.
  const auto foreign = configError("[Detection]\ndetector = hog\nmiss_rate = 0.1\n");
  EXPECT_NE(foreign.find("unknown key 'miss_rate' in section [Detection] of test.ini"),
            std::string::npos)
      << foreign;
  EXPECT_NE(foreign.find("min_height"), std::string::npos) << foreign;  // lists the valid keys
  EXPECT_NE(configError("[Detection]\ndetector = hog\nmode = fast\n").find("mode = 'fast'"),
            std::string::npos);
  EXPECT_NE(configError("[Detection]\ndetector = hog\nclass_map = person:human:non_rigid\n")
                .find("class_map in [Detection] of test.ini"),
            std::string::npos);
  EXPECT_NE(configError("[Detection]\nlayout = yolov7\n").find("'yolov7'"), std::string::npos);
  const auto model = configError("[Detection]\nmodel = /nowhere/m.onnx\n");
  EXPECT_NE(model.find("'/nowhere/m.onnx'"), std::string::npos) << model;
  EXPECT_NE(model.find("[Detection] of test.ini"), std::string::npos) << model;
  EXPECT_NE(configError("[Detection]\ndetector = ground_truth\n").find("objects is empty"),
            std::string::npos);
  // Values out of a key's range, each named with the file.
  for (const char* bad :
       {"detector = hog\nscale = 1", "detector = hog\nmin_height = 8", "confidence = 1",
        "nms_iou = 0", "threads = -1", "input_size = 16", "detector = ground_truth\nmiss_rate = 2",
        "detector = ground_truth\nseed = -1", "detector = ground_truth\njitter_px = -3"}) {
    const auto error = configError(std::string("[Detection]\n") + bad + "\n");
    const std::string key = std::string(bad).substr(std::string(bad).rfind('\n') + 1);
    EXPECT_NE(error.find(key.substr(0, key.find(' '))), std::string::npos) << bad << ": " << error;
    EXPECT_NE(error.find("test.ini"), std::string::npos) << bad << ": " << error;
  }
}

TEST(DetectionStage, DeterministicModeDetectsEveryFrameInline) {
  det::DetectionStage stage;
  stage.configure(IniConfig::fromText(
                      "[Detection]\ndetector = ground_truth\nobjects = " + writeObjects(10) + "\n"),
                  "Detection");
  for (int f = 0; f < 10; ++f) {
    auto frame = frameAt(f);
    stage.process(frame);
    EXPECT_TRUE(frame.detections_fresh);
    ASSERT_EQ(frame.detections.size(), 1u);
    EXPECT_EQ(frame.detections[0].truth_id, 5);
    EXPECT_EQ(frame.detections[0].box.x, 10.f + f);  // this very frame's box
  }
  stage.finish();
  EXPECT_EQ(stage.freshFrames(), 10u);
}

TEST(DetectionStage, ALongRunKeepsABoundedRecordOfSourceFrames) {
  const std::size_t frames = 2 * det::DetectionStage::kSourceFramesKept + 500;
  det::DetectionStage stage;
  stage.configure(IniConfig::fromText("[Detection]\ndetector = ground_truth\nobjects = " +
                                      writeObjects(int(frames)) + "\n"),
                  "Detection");
  for (std::size_t f = 0; f < frames; ++f) {
    auto frame = frameAt(int(f));
    stage.process(frame);
  }
  EXPECT_EQ(stage.freshFrames(), frames);
  const auto& sources = stage.sourceFrames();
  EXPECT_LE(sources.size(), 2 * det::DetectionStage::kSourceFramesKept);
  EXPECT_GE(sources.size(), det::DetectionStage::kSourceFramesKept);
  EXPECT_EQ(sources.back(), frames - 1) << "the newest are kept";
}

TEST(DetectionStage, RealtimeModeDeliversEarlierFramesResultsInOrder) {
  det::DetectionStage stage;
  const int frames = 3000;
  stage.configure(IniConfig::fromText("[Detection]\ndetector = ground_truth\nmode = realtime\n"
                                      "objects = " +
                                      writeObjects(frames) + "\n"),
                  "Detection");
  // Frames come at most every 2 ms (the rest of a pipeline takes time too), until the detector
  // thread has delivered a few results: however loaded the machine, the loop ends.
  for (int f = 0; f < frames && stage.freshFrames() < 10; ++f) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    auto frame = frameAt(f);
    stage.process(frame);
    if (!frame.detections_fresh) {
      EXPECT_TRUE(frame.detections.empty());
      continue;
    }
    const std::size_t source = stage.sourceFrames().back();
    EXPECT_LT(source, frame.index);  // a result always comes from an earlier image
    ASSERT_EQ(frame.detections.size(), 1u);
    EXPECT_EQ(frame.detections[0].box.x, 10.f + static_cast<float>(source));
  }
  stage.finish();
  EXPECT_GT(stage.freshFrames(), 0u);
  const auto& sources = stage.sourceFrames();
  for (std::size_t i = 1; i < sources.size(); ++i) EXPECT_LT(sources[i - 1], sources[i]);
}

TEST(DetectionStage, EveryKeyWrittenIsReadBackForEachDetector) {
  det::DetectionOptions written;
  written.mode = "realtime";
  written.class_map = "person:person:non_rigid bus:car:rigid";
  written.onnx_yolo = {"m.onnx", det::YoloLayout::YoloV8, 320, 0.5, 0.6, 1, false};
  written.hog = {1.1, 0.3, 16, 96, 0.3};
  written.ground_truth.objects = "o.txt";
  written.ground_truth.miss_rate = 0.1;
  written.ground_truth.jitter_px = 3;
  written.ground_truth.false_positive_rate = 0.2;
  written.ground_truth.min_visible_fraction = 0.4;
  written.ground_truth.seed = 7;
  for (const char* detector : {"onnx_yolo", "hog", "ground_truth"}) {
    written.detector = detector;
    mrpt::config::CConfigFileMemory saved;
    written.saveToConfigFile(saved, "Detection");
    // Through text, as a user's file is read (MRPT keeps the padding of written key names).
    const auto ini = dynslam::core::IniConfig::fromText(saved.getContent());
    det::DetectionOptions read;
    read.loadFromConfigFile(ini.ini(), "Detection");
    EXPECT_EQ(read.detector, written.detector);
    EXPECT_EQ(read.mode, "realtime");
    EXPECT_EQ(read.class_map, written.class_map);
    if (written.detector == "onnx_yolo") {
      EXPECT_EQ(read.onnx_yolo.model, "m.onnx");
      EXPECT_EQ(read.onnx_yolo.layout, det::YoloLayout::YoloV8);
      EXPECT_EQ(read.onnx_yolo.input_size, 320);
      EXPECT_DOUBLE_EQ(read.onnx_yolo.confidence, 0.5);
      EXPECT_DOUBLE_EQ(read.onnx_yolo.nms_iou, 0.6);
      EXPECT_EQ(read.onnx_yolo.threads, 1);
      EXPECT_FALSE(read.onnx_yolo.trim_padding);
    } else if (written.detector == "hog") {
      EXPECT_DOUBLE_EQ(read.hog.scale, 1.1);
      EXPECT_DOUBLE_EQ(read.hog.hit_threshold, 0.3);
      EXPECT_EQ(read.hog.win_stride, 16);
      EXPECT_EQ(read.hog.min_height, 96);
      EXPECT_DOUBLE_EQ(read.hog.nms_iou, 0.3);
    } else {
      const auto& g = read.ground_truth;
      EXPECT_EQ(g.objects, "o.txt");
      EXPECT_DOUBLE_EQ(g.miss_rate, 0.1);
      EXPECT_DOUBLE_EQ(g.jitter_px, 3);
      EXPECT_DOUBLE_EQ(g.false_positive_rate, 0.2);
      EXPECT_DOUBLE_EQ(g.min_visible_fraction, 0.4);
      EXPECT_EQ(g.seed, 7);
    }
  }
}
