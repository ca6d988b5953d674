// YOLOX-nano through OpenCV DNN finds the people of real images (opencv-doc's basketball1.png and
// sampled vtest.avi frames); a missing or unreadable model is an error naming its path.
#include "OpenCvDocImages.h"

#include <dynslam/detection/OnnxYoloDetector.h>
#include <dynslam/testing/TestEnv.h>

#include <opencv2/imgcodecs.hpp>

#include <gtest/gtest.h>

namespace det = dynslam::detection;
namespace dt = dynslam::testing;

namespace {

int confidentPeople(const std::vector<dynslam::core::Detection>& detections, float min_score) {
  int n = 0;
  for (const auto& d : detections) n += d.category == "person" && d.score > min_score;
  return n;
}

std::string errorOf(const det::OnnxYoloDetectorSettings& settings) {
  try {
    det::OnnxYoloDetector detector(settings, det::ClassMap());
  } catch (const det::DetectorError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OnnxYoloDetector, MissingOrUnreadableModelIsAnErrorNamingThePath) {
  const std::string dir = dt::scratchDir();
  det::OnnxYoloDetectorSettings settings;
  settings.model = dir + "/absent.onnx";
  EXPECT_NE(errorOf(settings).find("'" + settings.model + "' (missing or unreadable)"),
            std::string::npos)
      << errorOf(settings);
  settings.model = dt::writeTextFile(dir + "/garbage.onnx", "this is not a protobuf");
  EXPECT_NE(errorOf(settings).find("cannot load the YOLO model '" + settings.model + "'"),
            std::string::npos)
      << errorOf(settings);
  settings.input_size = 400;
  EXPECT_NE(errorOf(settings).find("multiple of 32"), std::string::npos);
}

TEST(OnnxYoloDetector, YoloxNanoFindsBothPlayersInBasketball1AtInput416And320) {
  DYNSLAM_REQUIRE_SHARED(model, "models/yolox_nano.onnx");
  DYNSLAM_REQUIRE_OPENCV_DOC(image_path, "basketball1.png");
  const cv::Mat image = cv::imread(image_path);
  for (const int input_size : {416, 320})
    for (const bool trim : {true, false}) {
      det::OnnxYoloDetectorSettings settings;
      settings.model = model;
      settings.input_size = input_size;
      settings.trim_padding = trim;
      det::OnnxYoloDetector detector(settings, det::ClassMap());
      const auto found = detector.detectImage(image);
      // Two players, one in each half of the 640x480 image, each about 400 px tall.
      ASSERT_EQ(confidentPeople(found, 0.7f), 2) << "input " << input_size << ", trim " << trim;
      bool left = false, right = false;
      for (const auto& d : found) {
        EXPECT_GT(d.box.height, 350.f);
        EXPECT_EQ(d.model, dynslam::core::MotionModel::NonRigid);
        (d.box.x + 0.5f * d.box.width < 320 ? left : right) = true;
      }
      EXPECT_TRUE(left && right) << "input " << input_size << ", trim " << trim;
    }
}

TEST(OnnxYoloDetector, TrimmedPaddingFindsTheSameBoxesAsTheSquareInput) {
  DYNSLAM_REQUIRE_SHARED(model, "models/yolox_nano.onnx");
  DYNSLAM_REQUIRE_OPENCV_DOC(video, "vtest.avi");
  const auto frames = det::testing::vtestFrames({0, 300, 600});
  ASSERT_EQ(frames.size(), 3u);
  det::OnnxYoloDetectorSettings settings;
  settings.model = model;
  det::OnnxYoloDetector trimmed(settings, det::ClassMap());
  settings.trim_padding = false;
  det::OnnxYoloDetector square(settings, det::ClassMap());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto a = trimmed.detectImage(frames[i]), b = square.detectImage(frames[i]);
    // The network sees the same pixels: each confident square-input box has a trimmed twin.
    int confident = 0;
    for (const auto& s : b) {
      if (s.score < 0.5f) continue;
      ++confident;
      double best = 0;
      for (const auto& t : a)
        best = std::max(best, double((s.box & t.box).area()) / (s.box | t.box).area());
      EXPECT_GT(best, 0.8) << "frame " << i << ": box at " << s.box.x << "," << s.box.y;
    }
    EXPECT_GE(confident, 3) << "frame " << i;
  }
}

TEST(OnnxYoloDetector, YoloxNanoFindsPeopleInSampledVtestFrames) {
  DYNSLAM_REQUIRE_SHARED(model, "models/yolox_nano.onnx");
  DYNSLAM_REQUIRE_OPENCV_DOC(video, "vtest.avi");
  const auto frames = det::testing::vtestFrames({0, 150, 300, 450, 600});
  ASSERT_EQ(frames.size(), 5u) << "cannot decode " << video;
  det::OnnxYoloDetectorSettings settings;
  settings.model = model;
  det::OnnxYoloDetector detector(settings, det::ClassMap());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    dynslam::core::Frame frame;
    frame.index = i;
    frame.rgb = frames[i];
    const auto found = detector.detect(frame);
    // Each of these frames shows three to six walkers at least 60 px tall.
    EXPECT_GE(confidentPeople(found, 0.7f), 3) << "sample " << i;
    for (const auto& d : found) {
      EXPECT_GE(d.box.x, 0.f);
      EXPECT_LE(d.box.x + d.box.width, 768.f);
    }
  }
}

TEST(OnnxYoloDetector, ClassMapDropsUnmappedClasses) {
  DYNSLAM_REQUIRE_SHARED(model, "models/yolox_nano.onnx");
  DYNSLAM_REQUIRE_OPENCV_DOC(video, "vtest.avi");
  const auto frames = det::testing::vtestFrames({0});
  ASSERT_EQ(frames.size(), 1u);
  det::OnnxYoloDetectorSettings settings;
  settings.model = model;
  det::OnnxYoloDetector cars_only(settings, det::ClassMap::parse("car:car:rigid"));
  const auto found = cars_only.detectImage(frames[0]);
  // The first frame shows cars (parked, top right) beside the people: only they are left.
  ASSERT_FALSE(found.empty());
  for (const auto& d : found) EXPECT_EQ(d.category, "car");
}
