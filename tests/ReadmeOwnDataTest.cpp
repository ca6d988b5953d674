// README.md's "Run it on your own data" commands, run verbatim: every ```sh block that follows a
// line `<!-- test: own-data outputs: FILE... -->` is run with `bash -e` (any failing command fails
// it) from the repository root, with B (the programs), D (../shared/data) and OUT (a scratch
// folder) in its environment; it must exit 0 and leave each listed FILE, non-empty, in OUT (a
// summary.json must say "status": "ok").
#include <dynslam/testing/TestEnv.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::scratchDir;
using dynslam::testing::sharedDir;
using dynslam::testing::sourceDir;
using dynslam::testing::writeTextFile;

namespace {

constexpr const char* kMarker = "<!-- test: own-data outputs:";

struct MarkedBlock {
  size_t line = 0;                   ///< 1-based line of the marker in README.md
  std::vector<std::string> outputs;  ///< files the block must leave in $OUT
  std::string script;                ///< the block's lines, as written
};

/// Every marked block of `readme`; a marker not followed by a ```sh block gives a block with an
/// empty script, which the tests report.
std::vector<MarkedBlock> markedBlocks(const std::string& readme) {
  std::vector<MarkedBlock> blocks;
  std::istringstream in(readme);
  std::string line;
  size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind(kMarker, 0) != 0) continue;
    MarkedBlock block;
    block.line = number;
    std::istringstream outputs(line.substr(std::string(kMarker).size()));
    for (std::string word; outputs >> word && word != "-->";) block.outputs.push_back(word);
    if (std::getline(in, line)) {
      ++number;
      if (line == "```sh") {
        while (std::getline(in, line)) {
          ++number;
          if (line == "```") break;
          block.script += line + "\n";
        }
      }
    }
    blocks.push_back(block);
  }
  return blocks;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

TEST(ReadmeOwnData, MarksItsCommandBlocksWithTheirOutputs) {
  const auto blocks = markedBlocks(readTextFile(sourceDir() + "/README.md"));
  ASSERT_GE(blocks.size(), 2u) << "README.md marks fewer than two blocks with " << kMarker;
  for (const auto& b : blocks) {
    EXPECT_FALSE(b.script.empty()) << "README.md line " << b.line << ": no ```sh block follows";
    EXPECT_FALSE(b.outputs.empty()) << "README.md line " << b.line << ": no outputs listed";
  }
}

TEST(ReadmeOwnData, RunsEachMarkedBlockVerbatim) {
  DYNSLAM_REQUIRE_SHARED(scenes, "data/7scenes");
  DYNSLAM_REQUIRE_SHARED(euroc, "data/euroc_v102_imu");
  const auto blocks = markedBlocks(readTextFile(sourceDir() + "/README.md"));
  ASSERT_FALSE(blocks.empty());
  const std::string dir = scratchDir();
  for (size_t i = 0; i < blocks.size(); ++i) {
    const auto& b = blocks[i];
    SCOPED_TRACE("README.md line " + std::to_string(b.line));
    const std::string out = dir + "/out" + std::to_string(i);
    const std::string script = writeTextFile(dir + "/block" + std::to_string(i) + ".sh", b.script);
    const auto r = runCommand("cd " + quoted(sourceDir()) + " && B=" + quoted(binDir()) +
                              " D=" + quoted(sharedDir() + "/data") + " OUT=" + quoted(out) +
                              " bash -e " + quoted(script));
    ASSERT_EQ(r.exit_code, 0) << b.script << r.output;
    for (const auto& name : b.outputs) {
      const fs::path file = fs::path(out) / name;
      ASSERT_TRUE(fs::is_regular_file(file)) << file << " is missing\n" << r.output;
      EXPECT_GT(fs::file_size(file), 0u) << file;
      if (file.filename() == "summary.json") {
        EXPECT_NE(readTextFile(file.string()).find("\"status\": \"ok\""), std::string::npos)
            << readTextFile(file.string());
      }
    }
  }
}
