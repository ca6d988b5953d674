#include <dynslam/core/ProgressReporter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

using dynslam::core::ProgressReporter;

namespace {
std::string readAll(std::FILE* f) {
  std::rewind(f);
  std::string s;
  char buf[512];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  return s;
}
}  // namespace

TEST(ProgressReporter, TerminalBarRedrawsInPlaceWithRateAndEta) {
  std::FILE* f = std::tmpfile();
  ProgressReporter p(f, true);
  p.update(10, 0.25);
  std::this_thread::sleep_for(std::chrono::milliseconds(120));
  p.update(20, 0.5);
  p.finish(40);
  const std::string out = readAll(f);
  std::fclose(f);
  EXPECT_NE(out.find("\r[###############..............."), std::string::npos) << out;
  EXPECT_NE(out.find(" 50% | 20 frames"), std::string::npos) << out;
  EXPECT_NE(out.find("fps"), std::string::npos);
  EXPECT_NE(out.find("ETA"), std::string::npos);
  EXPECT_NE(out.find("processed 40 frames"), std::string::npos);
}

TEST(ProgressReporter, PlainLinesForLogsAtTheInterval) {
  std::FILE* f = std::tmpfile();
  ProgressReporter p(f, false, 0.05);
  p.update(1, 0.1);  // before the first interval: nothing
  std::this_thread::sleep_for(std::chrono::milliseconds(80));
  p.update(5, 0.5);
  const std::string out = readAll(f);
  std::fclose(f);
  EXPECT_EQ(out.find('\r'), std::string::npos) << "no control characters in logs";
  EXPECT_EQ(out.find("[dynslam]  10%"), std::string::npos) << out;
  EXPECT_NE(out.find("[dynslam]  50% | 5 frames"), std::string::npos) << out;
}

TEST(ProgressReporter, DurationsReadLikeAPersonWouldWriteThem) {
  EXPECT_EQ(ProgressReporter::formatDuration(42.4), "42s");
  EXPECT_EQ(ProgressReporter::formatDuration(65), "1m05s");
  EXPECT_EQ(ProgressReporter::formatDuration(3 * 3600 + 120), "3h02m");
  EXPECT_EQ(ProgressReporter::formatDuration(NAN), "?");
}
