// The pieces of dynslam-sweep without running anything: grid parsing, job folders, job lines,
// the summary.json reader.
#include "sweep/SummaryJson.h"
#include "sweep/SweepGrid.h"
#include "sweep/SweepJobs.h"

#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <set>

using namespace dynslam::sweep;

namespace {

std::string gridError(const std::string& grid) {
  try {
    parseGrid(grid);
  } catch (const GridError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SweepGrid, ParsesKeysAndValuesInOrder) {
  const auto keys = parseGrid(" RgbdOdometry.min_depth = 0.3, 0.5 ;Tracking.max_age=5,10,20;");
  ASSERT_EQ(keys.size(), 2u);
  EXPECT_EQ(keys[0].name(), "RgbdOdometry.min_depth");
  EXPECT_EQ(keys[0].values, (std::vector<std::string>{"0.3", "0.5"}));
  EXPECT_EQ(keys[1].section, "Tracking");
  EXPECT_EQ(keys[1].key, "max_age");
  EXPECT_EQ(keys[1].values.size(), 3u);
}

TEST(SweepGrid, ErrorsNameTheBadPart) {
  EXPECT_NE(gridError("A.b=1;Tracking.max_age").find("'Tracking.max_age'"), std::string::npos);
  EXPECT_NE(gridError("A.b=1;max_age=3").find("'max_age=3'"), std::string::npos);
  EXPECT_NE(gridError("A.b=1,,2").find("empty value"), std::string::npos);
  EXPECT_NE(gridError("A.b=1;A.b=2").find("swept twice"), std::string::npos);
  EXPECT_NE(gridError("A.b=1,1").find("given twice"), std::string::npos);
  EXPECT_NE(gridError(" ; ").find("names no key"), std::string::npos);
  EXPECT_EQ(gridError("A.b=1"), "");
}

TEST(SweepGrid, EveryCombinationOnceLastKeyFastest) {
  const auto keys = parseGrid("A.a=1,2;B.b=x,y,z");
  const auto all = combinations(keys);
  ASSERT_EQ(all.size(), 6u);
  EXPECT_EQ(overridesOf(keys, all[0]), (std::vector<std::string>{"A.a=1", "B.b=x"}));
  EXPECT_EQ(overridesOf(keys, all[1]), (std::vector<std::string>{"A.a=1", "B.b=y"}));
  EXPECT_EQ(overridesOf(keys, all[5]), (std::vector<std::string>{"A.a=2", "B.b=z"}));
  std::set<std::vector<size_t>> distinct;
  for (const auto& c : all) distinct.insert(c.value_index);
  EXPECT_EQ(distinct.size(), 6u);
}

TEST(SweepJobs, FoldersAreReadableUniqueAndBounded) {
  SweepSpec spec;
  spec.dynslam = "bin/dynslam";
  spec.config = "my params.ini";
  spec.rawlogs = {"/data/a/seq.rawlog", "/data/b/seq.rawlog", "walk.rawlog"};
  spec.out = "out";
  spec.keys = parseGrid(
      "RgbdOdometry.method=rgbd,icp;Estimator.some_very_long_key_name_to_force_"
      "hashing_of_the_folder=" +
      std::string(60, '1') + "," + std::string(60, '2'));
  const auto jobs = makeJobs(spec);
  ASSERT_EQ(jobs.size(), 12u);
  std::set<std::string> names;
  for (const auto& j : jobs) {
    names.insert(j.name);
    EXPECT_LE(j.name.size(), 96u) << j.name;
    EXPECT_EQ(j.dir, "out/jobs/" + j.name);
  }
  EXPECT_EQ(names.size(), jobs.size()) << "two jobs share a folder";
  EXPECT_EQ(jobs[0].name.rfind("seq-", 0), 0u) << "same stems get a path hash: " << jobs[0].name;
  EXPECT_NE(jobs[0].name.find("RgbdOdometry.method=rgbd"), std::string::npos) << jobs[0].name;

  SweepSpec small = spec;
  small.rawlogs = {"walk.rawlog"};
  small.keys = parseGrid("RgbdOdometry.method=rgbd,icp");
  const auto two = makeJobs(small);
  EXPECT_EQ(two[1].name, "walk__RgbdOdometry.method=icp");
  // The job line keeps the paths as given (valid on other hosts), quotes what needs it and
  // skips a job already done.
  const std::string line = shellLine(small, two[1]);
  EXPECT_NE(line.find("bin/dynslam --config 'my params.ini' --rawlog walk.rawlog --out "
                      "out/jobs/walk__RgbdOdometry.method=icp --quiet --no-map --set "
                      "RgbdOdometry.method=icp"),
            std::string::npos)
      << line;
  EXPECT_EQ(
      line.rfind(
          "grep -qs '\"status\": \"ok\"' out/jobs/walk__RgbdOdometry.method=icp/summary.json || ",
          0),
      0u)
      << line;
  EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
}

TEST(SweepJobs, SlurmScriptIsAJobArrayOverTheJobList) {
  SweepSpec spec;
  spec.dynslam = "dynslam";
  spec.config = "c.ini";
  spec.rawlogs = {"r.rawlog"};
  spec.out = dynslam::testing::scratchDir();
  spec.keys = parseGrid("A.a=1,2;B.b=3,4,5");
  const auto jobs = makeJobs(spec);
  const std::string list = writeJobList(spec, jobs);
  const std::string script = dynslam::testing::readTextFile(writeSlurmScript(spec, jobs, list, 2));
  EXPECT_NE(script.find("#SBATCH --array=0-5%2\n"), std::string::npos) << script;
  EXPECT_NE(script.find("SLURM_ARRAY_TASK_ID + 1"), std::string::npos) << script;
  const std::string lines = dynslam::testing::readTextFile(list);
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 6);
}

TEST(SummaryJson, ReadsTopLevelScalarsAndSkipsNestedValues) {
  const std::string dir = dynslam::testing::scratchDir();
  dynslam::testing::writeTextFile(
      dir + "/summary.json",
      "{\n  \"status\": \"failed\",\n  \"error\": \"unknown key 'x' in \\\"[A]\\\"\",\n"
      "  \"overrides\": [\"a}\", \"b\"],\n  \"stages\": [{\"name\": \"fps\", \"fps\": 3}],\n"
      "  \"fps\": 25.5,\n  \"estimator\": true\n}\n");
  const auto s = readRunSummary(dir + "/summary.json");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->get("status"), "failed");
  EXPECT_EQ(s->get("error"), "unknown key 'x' in \"[A]\"");
  EXPECT_EQ(s->number("fps"), 25.5);
  EXPECT_EQ(s->get("estimator"), "true");
  EXPECT_FALSE(jobCompleted(dir));
  dynslam::testing::writeTextFile(dir + "/summary.json", "{\n  \"status\": \"ok\",\n  \"fr");
  EXPECT_FALSE(readRunSummary(dir + "/summary.json")) << "a half-written file is no summary";
  dynslam::testing::writeTextFile(dir + "/summary.json", "{\"status\": \"ok\"}");
  EXPECT_TRUE(jobCompleted(dir));
  EXPECT_FALSE(jobCompleted(dir + "/absent"));
}
