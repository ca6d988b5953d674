// The installed package as an embedding program sees it: `cmake --install` into a temporary
// prefix, examples/embed configured with find_package(dynslam REQUIRED) and built against it,
// then run on a simulated rawlog: the same trajectory as the dynslam program's, byte for byte.
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

TEST(Install, AnOutOfTreeProgramFindsThePackageAndGetsTheTrajectoryDynslamWrites) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string prefix = dir + "/prefix", build = dir + "/embed-build", sim = dir + "/sim";
  const auto install = runCommand("cmake --install " DYNSLAM_BUILD_DIR " --prefix " + prefix);
  ASSERT_EQ(install.exit_code, 0) << install.output;
  for (const char* installed :
       {"/bin/dynslam", "/include/dynslam/system/System.h",
        "/lib/cmake/dynslam/dynslamConfig.cmake", "/lib/cmake/dynslam/dynslamConfigVersion.cmake",
        "/share/dynslam/params/sim_vio.ini"})
    EXPECT_TRUE(std::filesystem::exists(prefix + installed)) << installed;

  const auto configure = runCommand("cmake -S " + sourceDir() + "/examples/embed -B " + build +
                                    " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + prefix);
  ASSERT_EQ(configure.exit_code, 0) << configure.output;
  const auto compile = runCommand("cmake --build " + build + " -j2");
  ASSERT_EQ(compile.exit_code, 0) << compile.output;

  const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                 "/params/sim/indoor_people_high.ini --out " + sim +
                                 " --set Scenario.duration=2 --quiet");
  ASSERT_EQ(render.exit_code, 0) << render.output;
  // The installed ini, with the ground-truth detector on this rawlog; solves end on their
  // iteration count, so the two runs can be compared byte for byte.
  const std::string sets = " Detection.objects=" + sim + "/objects.txt" +
                           " Estimator.dynamic_handling=full Estimator.max_solver_time=100";
  const auto embed = runCommand(build + "/embed " + prefix + "/share/dynslam/params/sim_vio.ini " +
                                sim + "/sim.rawlog " + dir + "/embed.tum" + sets);
  ASSERT_EQ(embed.exit_code, 0) << embed.output;
  EXPECT_NE(embed.output.find("status tracking"), std::string::npos) << embed.output;

  const auto run = runCommand(
      binDir() + "/dynslam --config " + sourceDir() + "/params/sim_vio.ini --rawlog " + sim +
      "/sim.rawlog --out " + dir + "/run --no-map --quiet --set Detection.objects=" + sim +
      "/objects.txt --set Estimator.dynamic_handling=full --set Estimator.max_solver_time=100");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string expected = readTextFile(dir + "/run/trajectory.tum");
  EXPECT_GT(expected.size(), 1000u);
  EXPECT_EQ(readTextFile(dir + "/embed.tum"), expected);
}

}  // namespace
