// 200 mutated inputs of each kind through the programs that read them (bench-fuzz-inputs with a
// fixed seed): every case ends with exit 0, or exit 1 naming its file; no signal, no hang, no
// run beyond 2 GB. The bench itself runs 10,000 (docs/benchmarks.md).
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <iostream>

namespace dt = dynslam::testing;

namespace {

#ifdef DYNSLAM_SANITIZED
// Instrumented programs run 3-10 x slower and need terabytes of address space: fewer cases,
// no address-space limit; what the sanitizers find exits 66 ("other exits").
const char* const kCases = "50 --memory-mb 0";
const char* const kCounted = "50 cases: exit 0";
#else
const char* const kCases = "200";
const char* const kCounted = "200 cases: exit 0";
#endif

void fuzz(const std::string& kind) {
  const std::string out = dt::scratchDir() + "/fuzz";
  const auto r = dt::runCommand(dt::binDir() + "/bench-fuzz-inputs --seed 1 --cases " + kCases +
                                " --kinds " + kind + " --out " + out + " 2>&1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(kind + " "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(kCounted), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("signals 0, hangs 0, other exits 0, errors naming no file 0"),
            std::string::npos)
      << r.output;
  std::cout << r.output;
}

}  // namespace

TEST(FuzzInputs, Rawlogs) { fuzz("rawlog"); }
TEST(FuzzInputs, IniFiles) { fuzz("ini"); }
TEST(FuzzInputs, TrajectoryFiles) { fuzz("trajectory"); }
TEST(FuzzInputs, SevenScenesFolders) { fuzz("sevenscenes"); }
TEST(FuzzInputs, TumFolders) { fuzz("tum"); }
