// Cutting people out of video (VideoForeground, SpriteExtractor, SpriteBank) on a synthetic
// static-camera video with each figure's true mask (testing/SyntheticWalkers.h).
#include <dynslam/sim/SpriteExtractor.h>
#include <dynslam/testing/SyntheticWalkers.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <fstream>

namespace dynslam::sim {
namespace {

using testing::SyntheticWalker;
using testing::SyntheticWalkerScene;

/// The scene's median background from every third frame, and the extractor run over it.
SpriteBank extract(const SyntheticWalkerScene& scene, SpriteExtractionReport* report = nullptr) {
  std::vector<cv::Mat> samples;
  for (int i = 0; i < scene.frames; i += 3) samples.push_back(scene.frame(i));
  SpriteExtractor extractor(medianBackground(samples));
  for (int i = 0; i < scene.frames; ++i) extractor.add(scene.frame(i));
  SpriteBank bank = extractor.finish("synthetic.avi");
  if (report) *report = extractor.report();
  return bank;
}

/// The sprite's alpha placed in a full frame.
cv::Mat alphaInFrame(const SpriteFrame& f, cv::Size size) {
  cv::Mat full(size, CV_8UC1, cv::Scalar(0)), alpha;
  cv::extractChannel(f.bgra, alpha, 3);
  alpha.copyTo(full(cv::Rect(f.crop_origin, alpha.size())));
  return full;
}

double maskIou(const cv::Mat& a, const cv::Mat& b) {
  return double(cv::countNonZero(a & b)) / std::max(1, cv::countNonZero(a | b));
}

SyntheticWalkerScene oneWalker() {
  SyntheticWalkerScene scene;
  scene.walkers.push_back({{80, 320}, {560, 320}});
  return scene;
}

TEST(SpriteExtractor, AWalkerComesOutWithItsMaskAndFootPoint) {
  const SyntheticWalkerScene scene = oneWalker();
  SpriteExtractionReport report;
  const SpriteBank bank = extract(scene, &report);
  ASSERT_EQ(bank.sequences.size(), 1u);
  const auto& frames = bank.sequences[0].frames;
  EXPECT_EQ(frames.size(), size_t(scene.frames)) << "every frame: the walker stays in view";
  for (const auto& f : frames) {
    std::vector<cv::Mat> truth;
    scene.frame(f.video_frame, &truth);
    EXPECT_GE(maskIou(alphaInFrame(f, scene.size), truth[0]), 0.9) << "frame " << f.video_frame;
    const cv::Point2f foot = cv::Point2f(f.crop_origin) + f.foot;
    EXPECT_LE(cv::norm(foot - footPointOfMask(truth[0])), 2.0) << "frame " << f.video_frame;
    EXPECT_NEAR(f.height_px, 150, 3);
  }
  EXPECT_NEAR(frames.back().walked_heights, 480.0 / 150, 0.15) << "480 px walked at 150 px tall";
  EXPECT_GT(bank.sequences[0].footVelocity().x, 9) << "walking to the right, 10 px a frame";
  EXPECT_EQ(report.people, 1u);
  EXPECT_EQ(report.sprite_frames, size_t(scene.frames));
}

TEST(VideoForeground, ACastShadowIsNotForegroundAndAFigureIs) {
  const SyntheticWalkerScene scene;
  const cv::Mat background = scene.background();
  cv::Mat frame = background.clone();
  const cv::Rect shadow(100, 200, 120, 60), figure(400, 100, 40, 120);
  frame(shadow).convertTo(frame(shadow), -1, 0.65);  // darker, same colour
  frame(figure).setTo(cv::Scalar(40, 40, 200));
  const cv::Mat mask = foregroundMask(frame, background);
  EXPECT_LT(cv::countNonZero(mask(shadow)), shadow.area() / 50) << "the shadow stays background";
  EXPECT_GT(cv::countNonZero(mask(figure)), figure.area() * 95 / 100);
  const auto blobs = foregroundBlobs(mask, 80);
  ASSERT_EQ(blobs.size(), 1u);
  EXPECT_EQ(blobs[0].box, figure);
}

TEST(SpriteExtractor, TwoPeopleCrossingAreLeftOutWhileTheirBlobsTouch) {
  SyntheticWalkerScene scene;
  scene.frames = 64;
  scene.walkers.push_back({{60, 320}, {580, 320}});
  scene.walkers.push_back({{580, 318}, {60, 318}, 150, {40, 200, 40}, {200, 40, 200}});
  SpriteExtractionReport report;
  const SpriteBank bank = extract(scene, &report);
  EXPECT_GT(report.two_people, 0u) << "the frames they overlap";
  ASSERT_GE(bank.sequences.size(), 2u) << "each walker before and after the crossing";
  for (const auto& seq : bank.sequences)
    for (const auto& f : seq.frames) {
      std::vector<cv::Mat> truth;
      scene.frame(f.video_frame, &truth);
      const cv::Mat alpha = alphaInFrame(f, scene.size);
      EXPECT_GE(std::max(maskIou(alpha, truth[0]), maskIou(alpha, truth[1])), 0.9)
          << "a kept frame holds one person, frame " << f.video_frame;
    }
}

TEST(SpriteExtractor, APersonCutByTheBorderIsLeftOutThere) {
  SyntheticWalkerScene scene;
  scene.walkers.push_back({{-20, 320}, {460, 320}});  // enters through the left edge
  SpriteExtractionReport report;
  const SpriteBank bank = extract(scene, &report);
  EXPECT_GT(report.cut_by_border, 0u);
  ASSERT_EQ(bank.sequences.size(), 1u);
  for (const auto& f : bank.sequences[0].frames) EXPECT_GE(f.crop_origin.x, 1);
  EXPECT_LT(bank.sequences[0].frames.size(), size_t(scene.frames));
}

TEST(SpriteExtractor, AStretchShorterThanAGaitCycleIsLeftOut) {
  SyntheticWalkerScene scene;
  scene.walkers.push_back({{200, 320}, {260, 320}});  // 60 px at 150 px tall: 0.4 heights
  SpriteExtractionReport report;
  EXPECT_TRUE(extract(scene, &report).sequences.empty());
  EXPECT_EQ(report.short_stretches, 1u);
}

TEST(SpriteBank, WrittenTwiceTheSameBytesAndReadBack) {
  const SpriteBank bank = extract(oneWalker());
  const std::string dir = testing::scratchDir(), a = dir + "/bank_a", b = dir + "/bank_b";
  writeSpriteBank(bank, a);
  writeSpriteBank(extract(oneWalker()), b);
  EXPECT_EQ(testing::readTextFile(a + "/bank.txt"), testing::readTextFile(b + "/bank.txt"));
  EXPECT_EQ(testing::readTextFile(a + "/s000/f010.png"),
            testing::readTextFile(b + "/s000/f010.png"));
  const SpriteBank back = readSpriteBank(a);
  EXPECT_EQ(back.source, "synthetic.avi");
  ASSERT_EQ(back.frameCount(), bank.frameCount());
  const auto& f = back.sequences[0].frames[10];
  EXPECT_EQ(cv::norm(f.bgra, bank.sequences[0].frames[10].bgra, cv::NORM_INF), 0);
  EXPECT_NEAR(f.foot.x, bank.sequences[0].frames[10].foot.x, 0.01);
}

TEST(SpriteBank, AMissingOrBrokenBankIsAnErrorNamingTheFileAndLine) {
  const std::string dir = testing::scratchDir() + "/broken_bank";
  try {
    readSpriteBank(dir);
    FAIL() << "no bank.txt";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bank.txt"), std::string::npos) << e.what();
  }
  writeSpriteBank(extract(oneWalker()), dir);
  std::ofstream(dir + "/bank.txt", std::ios::app) << "0 99 3 oops\n";
  try {
    readSpriteBank(dir);
    FAIL() << "a malformed line";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 52"), std::string::npos) << e.what();
  }
  std::filesystem::remove(dir + "/s000/f003.png");
  std::ofstream(dir + "/bank.txt", std::ios::trunc) << "# dynslam sprite bank v1\n"
                                                    << "0 0 3 10 10 5 5 150 0\n"
                                                    << "0 1 4 10 10 5 5 150 0.1\n"
                                                    << "0 2 5 10 10 5 5 150 0.2\n"
                                                    << "0 3 6 10 10 5 5 150 0.3\n";
  try {
    readSpriteBank(dir);
    FAIL() << "a missing PNG";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("f003.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynslam::sim
