// dynslam-sprites as a program: a synthetic walker's video (MJPEG AVI, written here), Debian
// opencv-doc's vtest.avi (real pedestrians; skipped without opencv-doc), and bad input.
#include <dynslam/testing/SyntheticWalkers.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/videoio.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::scratchDir;

namespace {

const std::string kVtest = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";

std::string sprites(const std::string& args) {
  return binDir() + "/dynslam-sprites " + args + " 2>&1";
}

/// `scene` as an MJPEG AVI in `dir` (OpenCV's own writer: no codec library needed).
std::string writeVideo(const dynslam::testing::SyntheticWalkerScene& scene, const std::string& dir,
                       const std::string& name) {
  const std::string path = dir + "/" + name;
  cv::VideoWriter writer(path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         10, scene.size);
  EXPECT_TRUE(writer.isOpened()) << path;
  for (int i = 0; i < scene.frames; ++i) writer.write(scene.frame(i));
  return path;
}

}  // namespace

TEST(DynslamSprites, AWalkersVideoGivesABankAndAContactSheet) {
  dynslam::testing::SyntheticWalkerScene scene;
  scene.walkers.push_back({{80, 320}, {560, 320}});
  const std::string dir = scratchDir(), out = dir + "/walker_bank";
  const std::string video = writeVideo(scene, dir, "walker.avi");
  const auto run = runCommand(
      sprites("--video " + video + " --out " + out + " --contact-sheet " + out + "/sheet.png"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("kept 1 people of 1 followed: 1 sequences, 48 frames"),
            std::string::npos)
      << run.output;
  EXPECT_TRUE(fs::exists(out + "/bank.txt"));
  EXPECT_TRUE(fs::exists(out + "/s000/f047.png"));
  EXPECT_GT(fs::file_size(out + "/sheet.png"), 1000u);
}

TEST(DynslamSprites, BadInputIsAnErrorNamingItAndLeavesNoBank) {
  const std::string dir = scratchDir(), out = dir + "/bad_bank";
  auto run = runCommand(sprites("--video /nonexistent/video.avi --out " + out));
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("/nonexistent/video.avi: no such file"), std::string::npos)
      << run.output;

  const std::string notVideo = dir + "/not_a_video.avi";
  std::ofstream(notVideo) << "this is text\n";
  run = runCommand(sprites("--video " + notVideo + " --out " + out));
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find(notVideo), std::string::npos) << run.output;

  // A video without a moving person; an earlier bank in the folder must not survive as this
  // video's.
  fs::create_directories(out);
  std::ofstream(out + "/bank.txt") << "# dynslam sprite bank v1\n";
  dynslam::testing::SyntheticWalkerScene empty;
  run = runCommand(sprites("--video " + writeVideo(empty, dir, "empty.avi") + " --out " + out));
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("no walking person kept"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out + "/bank.txt"));

  run = runCommand(sprites("--out " + out));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--video"), std::string::npos) << run.output;
}

// Real pedestrians (static camera, 795 frames of 768x576): several people kept, the same bank
// byte for byte from two runs.
TEST(DynslamSprites, RealPedestriansFromVtestTheSameBankTwice) {
  if (!fs::exists(kVtest)) GTEST_SKIP() << kVtest << " is absent (Debian package opencv-doc)";
  const std::string dir = scratchDir(), a = dir + "/vtest_a", b = dir + "/vtest_b";
  const auto first = runCommand(sprites("--video " + kVtest + " --out " + a));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const auto second = runCommand(sprites("--video " + kVtest + " --out " + b));
  ASSERT_EQ(second.exit_code, 0) << second.output;
  std::smatch m;
  const std::regex kept(R"(kept (\d+) people of \d+ followed: (\d+) sequences, (\d+) frames)");
  ASSERT_TRUE(std::regex_search(first.output, m, kept)) << first.output;
  EXPECT_GE(std::stoi(m[1]), 3) << first.output;
  EXPECT_GE(std::stoi(m[3]), 60) << first.output;
  EXPECT_EQ(readTextFile(a + "/bank.txt"), readTextFile(b + "/bank.txt"));
  EXPECT_EQ(readTextFile(a + "/s000/f000.png"), readTextFile(b + "/s000/f000.png"));
}
