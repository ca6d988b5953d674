#pragma once
// Locations a test needs, taken from the environment CTest sets (see cmake/DynslamTargets.cmake).
#include <gtest/gtest.h>

#include <string>

namespace dynslam::testing {

/// ../shared beside the clone (DYNSLAM_SHARED_DIR).
std::string sharedDir();
/// sharedDir() + "/" + relative, or "" when that path does not exist.
std::string sharedPath(const std::string& relative);
/// build/bin, where the programs are (DYNSLAM_BIN_DIR).
std::string binDir();
/// The source tree (DYNSLAM_SOURCE_DIR), for params/ files.
std::string sourceDir();
/// A fresh, empty scratch folder for the calling test: <test-tmp>/<suite>.<test>[/sub].
std::string scratchDir(const std::string& sub = "");

/// The whole content of a file ("" when it cannot be read).
std::string readTextFile(const std::string& path);
/// Writes `text` to `path` (truncating) and returns the path.
std::string writeTextFile(const std::string& path, const std::string& text);

/// Output and exit code of a shell command (stdout and stderr together).
struct CommandResult {
  int exit_code = -1;
  std::string output;
};
CommandResult runCommand(const std::string& command);

}  // namespace dynslam::testing

/// Skips the current test, with the reason, when ../shared/<relative> is absent; otherwise
/// assigns its full path to `var`.
#define DYNSLAM_REQUIRE_SHARED(var, relative)                                      \
  const std::string var = ::dynslam::testing::sharedPath(relative);                \
  if (var.empty())                                                                 \
  GTEST_SKIP() << "needs " << ::dynslam::testing::sharedDir() << "/" << (relative) \
               << ", which is absent"
