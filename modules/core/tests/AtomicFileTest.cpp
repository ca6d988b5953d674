// Files written whole or not at all: the previous content stays until commit, nothing is left
// behind, and a failure names the file.
#include <dynslam/core/AtomicFile.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace core = dynslam::core;
namespace fs = std::filesystem;

namespace {

size_t filesIn(const std::string& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(AtomicFile, CommitReplacesTheFileAndLeavesNoTemporary) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string path = dir + "/summary.json";
  std::ofstream(path) << "{\"status\": \"old\"}\n";
  core::AtomicTextFile file(path);
  file.stream() << "{\"status\": \"ok\"}\n";
  EXPECT_EQ(dynslam::testing::readTextFile(path), "{\"status\": \"old\"}\n")
      << "replaced before commit";
  file.commit();
  EXPECT_EQ(dynslam::testing::readTextFile(path), "{\"status\": \"ok\"}\n");
  EXPECT_EQ(filesIn(dir), 1u) << "a temporary file was left beside it";
}

TEST(AtomicFile, AFileNeverCommittedIsNeverCreated) {
  const std::string dir = dynslam::testing::scratchDir();
  {
    core::AtomicTextFile file(dir + "/results.csv");
    file.stream() << "job,status\n0,ok\n";
  }
  EXPECT_EQ(filesIn(dir), 0u);
}

TEST(AtomicFile, AFailedWriteNamesTheFileAndKeepsThePreviousOne) {
  const std::string dir = dynslam::testing::scratchDir();
  try {
    core::writeFileAtomically(dir + "/no/such/folder/summary.json", "{}");
    FAIL() << "no error for a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/no/such/folder/summary.json"), std::string::npos)
        << e.what();
  }
  const std::string path = dir + "/map.3Dscene";
  std::ofstream(path) << "previous";
  EXPECT_THROW(core::replaceFileAtomically(path,
                                           [](const std::string& temporary) {
                                             std::ofstream(temporary) << "half a map";
                                             throw std::runtime_error("the writer failed");
                                           }),
               std::runtime_error);
  EXPECT_EQ(dynslam::testing::readTextFile(path), "previous");
  EXPECT_EQ(filesIn(dir), 1u) << "the failed writer's temporary was left";
  core::replaceFileAtomically(
      path, [](const std::string& temporary) { std::ofstream(temporary) << "the new map"; });
  EXPECT_EQ(dynslam::testing::readTextFile(path), "the new map");
  EXPECT_EQ(filesIn(dir), 1u);
}
