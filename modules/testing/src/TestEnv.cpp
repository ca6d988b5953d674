#include "dynslam/testing/TestEnv.h"

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace dynslam::testing {
namespace {
std::string envOr(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return (v && *v) ? std::string(v) : fallback;
}
}  // namespace

std::string sharedDir() { return envOr("DYNSLAM_SHARED_DIR", DYNSLAM_SHARED_DIR_DEFAULT); }

std::string sharedPath(const std::string& relative) {
  const fs::path p = fs::path(sharedDir()) / relative;
  return fs::exists(p) ? p.string() : std::string();
}

std::string binDir() { return envOr("DYNSLAM_BIN_DIR", DYNSLAM_BIN_DIR_DEFAULT); }

std::string sourceDir() { return envOr("DYNSLAM_SOURCE_DIR", DYNSLAM_SOURCE_DIR_DEFAULT); }

std::string scratchDir(const std::string& sub) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = fs::path(envOr("DYNSLAM_TEST_TMP", DYNSLAM_TEST_TMP_DEFAULT)) /
                 (std::string(info ? info->test_suite_name() : "suite") + "." +
                  (info ? info->name() : "test"));
  if (!sub.empty()) dir /= sub;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

CommandResult runCommand(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace dynslam::testing
