// The truncated-rawlog fixtures behave as documented (readers' truncation handling is tested
// by the io module).
#include <dynslam/rawlog_tools/ObservationBuilders.h>
#include <dynslam/rawlog_tools/RawlogWriter.h>
#include <dynslam/rawlog_tools/TruncatedRawlog.h>
#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

using namespace dynslam::rawlog_tools;

namespace {

void writeImuRawlog(const std::string& path, int samples) {
  RawlogWriter writer(path);
  for (int i = 0; i < samples; ++i)
    writer.write(*makeImuObservation(mrpt::Clock::fromDouble(100.0 + 0.005 * i), "IMU",
                                     std::array<double, 3>{0.1 * i, 0, 0},
                                     std::array<double, 3>{0, 0, 9.81}));
  writer.close();
}

/// Observations read before the stream ends or fails, and whether it failed.
std::pair<size_t, bool> readUntilTheEnd(const std::string& path) {
  mrpt::io::CFileGZInputStream file(path);
  auto in = mrpt::serialization::archiveFrom(file);
  mrpt::obs::CActionCollection::Ptr actions;
  mrpt::obs::CSensoryFrame::Ptr frame;
  mrpt::obs::CObservation::Ptr obs;
  size_t entry = 0, count = 0;
  try {
    while (
        mrpt::obs::CRawlog::getActionObservationPairOrObservation(in, actions, frame, obs, entry))
      ++count;
  } catch (const std::exception&) {
    return {count, true};
  }
  return {count, false};
}

}  // namespace

TEST(RawlogToolsTruncated, CutInsideObservationKeepsTheCompleteOnes) {
  const std::string dir = dynslam::testing::scratchDir();
  writeImuRawlog(dir + "/good.rawlog", 10);
  EXPECT_EQ(readUntilTheEnd(dir + "/good.rawlog"), std::make_pair(size_t{10}, false));
  EXPECT_GT(writeRawlogCutInsideObservation(dir + "/good.rawlog", dir + "/cut.rawlog", 5), 0u);
  EXPECT_EQ(readUntilTheEnd(dir + "/cut.rawlog").first, 5u);
  EXPECT_THROW(writeRawlogCutInsideObservation(dir + "/good.rawlog", dir + "/x.rawlog", 10),
               std::runtime_error);
}

TEST(RawlogToolsTruncated, RawByteCutHalvesTheFile) {
  const std::string dir = dynslam::testing::scratchDir();
  writeImuRawlog(dir + "/good.rawlog", 200);
  const auto size = std::filesystem::file_size(dir + "/good.rawlog");
  EXPECT_EQ(writeRawlogCutRawBytes(dir + "/good.rawlog", dir + "/crash.rawlog", 0.5), size / 2);
  EXPECT_EQ(std::filesystem::file_size(dir + "/crash.rawlog"), size / 2);
  EXPECT_LT(readUntilTheEnd(dir + "/crash.rawlog").first, 200u);
}

TEST(RawlogToolsWriter, DeletesAnUnclosedRawlog) {
  const std::string path = dynslam::testing::scratchDir() + "/unclosed.rawlog";
  {
    RawlogWriter writer(path);
    writer.write(*makeImuObservation(mrpt::Clock::fromDouble(1.0), "IMU", std::nullopt,
                                     std::array<double, 3>{0, 0, 9.81}));
    EXPECT_TRUE(std::filesystem::exists(path));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}
