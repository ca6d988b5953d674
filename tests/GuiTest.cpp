// dynslam --gui (issue 7): the live window on a few simulated frames under a virtual X display
// (xvfb-run), and its final picture saved with --gui-screenshot.
#include <dynslam/testing/TestEnv.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

namespace {

bool haveXvfbRun() { return runCommand("command -v xvfb-run && command -v Xvfb").exit_code == 0; }

/// One simulated second of indoor_people_high (params/sim), as RunnerOutputsTest renders it.
std::string simulate(const std::string& dir) {
  const auto r = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                            "/params/sim/indoor_people_high.ini --out " + dir +
                            " --set Scenario.duration=1 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir;
}

}  // namespace

TEST(Gui, AWindowUnderXvfbLeavesAScreenshotOfTheMapAndTheAnnotatedFrame) {
  if (!haveXvfbRun())
    GTEST_SKIP() << "needs xvfb-run and Xvfb (Debian package xvfb) for a virtual X display";
  const std::string dir = dynslam::testing::scratchDir();
  const std::string sim = simulate(dir + "/sim"), shot = dir + "/shot.png";
  ASSERT_FALSE(HasFailure());
  // softpipe: Mesa's llvmpipe reads the window back black under Xvfb (LiveView then draws the
  // scene off-screen); softpipe reads it back, so the window's own picture is what is tested.
  const auto run =
      runCommand("GALLIUM_DRIVER=softpipe xvfb-run -a -s '-screen 0 1280x1024x24' " + binDir() +
                 "/dynslam --config " + sourceDir() + "/params/sim_vio.ini --rawlog " + sim +
                 "/sim.rawlog --out " + dir + "/out --set Detection.objects=" + sim +
                 "/objects.txt --max-frames 12 --gui-screenshot " + shot + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("dynslam: wrote " + shot + " ("), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("dynslam: 12 frames"), std::string::npos) << run.output;

  ASSERT_TRUE(fs::exists(shot)) << run.output;
  const cv::Mat image = cv::imread(shot, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty()) << shot << " is not a readable image";
  EXPECT_EQ(image.size(), cv::Size(1024, 768)) << "the window's size (LiveViewOptions)";
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 5.0) << "a single-colour screenshot";
  // The annotated frame fills the lower-left corner: the simulated room's colours, not the
  // scene's flat background, so that corner varies much more than the 3-D view's top row.
  const cv::Mat corner = image(cv::Rect(10, 768 - 200, 300, 190));
  cv::meanStdDev(corner, mean, stddev);
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 30.0) << "no annotated frame in the corner";
  // The map and trajectory are drawn over the background: more than one colour outside it.
  const cv::Mat view = image(cv::Rect(400, 0, 624, 768));
  cv::meanStdDev(view, mean, stddev);
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 1.0) << "nothing drawn in the 3-D view";
}

TEST(Gui, WithoutADisplayGuiFailsAtOnceNamingTheProblemAndXvfbRun) {
  const std::string dir = dynslam::testing::scratchDir();
  const auto run =
      runCommand("env -u DISPLAY " + binDir() + "/dynslam --gui --config " + sourceDir() +
                 "/params/sim_vio.ini --rawlog " + dir + "/none.rawlog --out " + dir + "/out");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("$DISPLAY is not set"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("xvfb-run -a"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir + "/out/summary.json")) << "failed before any work";
}
