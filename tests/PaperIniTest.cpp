// params/paper.ini runs the method as method.md states it: the whole system on two simulated
// seconds, and every departure docs/design.md lists at the value its table says, both for the
// code's defaults (docs/parameters.md, generated from the code) and for paper.ini.
#include <dynslam/core/TrajectoryFile.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>

using dynslam::testing::binDir;
using dynslam::testing::readTextFile;
using dynslam::testing::runCommand;
using dynslam::testing::sourceDir;

namespace {

/// One row of design.md's departures table whose key is a single `Section.key`.
struct Departure {
  std::string section, key, shipped, paper;  ///< paper: "" when the ini leaves the key alone
};

std::vector<Departure> departuresInDesign() {
  std::istringstream in(readTextFile(sourceDir() + "/docs/design.md"));
  const std::regex row(R"(^\| `([A-Za-z]+)\.([a-z0-9_]+)` \| `([^`]*)`[^|]*\| ([^|]*)\|)");
  const std::regex value(R"(^\s*`([^`]*)`)");
  std::vector<Departure> out;
  for (std::string line; std::getline(in, line);) {
    std::smatch m, v;
    if (!std::regex_search(line, m, row)) continue;
    const std::string paperCell = m[4];
    out.push_back({m[1], m[2], m[3],
                   std::regex_search(paperCell, v, value) ? std::string(v[1]) : std::string()});
  }
  return out;
}

/// `[Section] key` -> default, from the parameter reference's tables for dynslam.
std::map<std::string, std::string> defaultsInReference() {
  std::istringstream in(readTextFile(sourceDir() + "/docs/parameters.md"));
  const std::regex heading(R"(^## `\[([A-Za-z]+)\]` \(dynslam\))");
  const std::regex row(R"(^\| `([a-z0-9_]+)` \| `([^`]*)`)");
  std::map<std::string, std::string> out;
  std::string section;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (line.rfind("## ", 0) == 0)
      section = std::regex_search(line, m, heading) ? std::string(m[1]) : std::string();
    else if (!section.empty() && std::regex_search(line, m, row))
      out[section + "." + std::string(m[1])] = m[2];
  }
  return out;
}

/// `Section.key` -> value, from `dynslam --print-config`'s output.
std::map<std::string, std::string> printedConfig(const std::string& text) {
  std::istringstream in(text);
  const std::regex sectionLine(R"(^\[([A-Za-z]+)\])"), keyLine(R"(^([a-z0-9_]+) = (\S*))");
  std::map<std::string, std::string> out;
  std::string section;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, sectionLine))
      section = m[1];
    else if (std::regex_search(line, m, keyLine))
      out[section + "." + std::string(m[1])] = m[2];
  }
  return out;
}

/// Equal as numbers when both are numbers ("0.20" and "0.2"), else as text.
bool sameValue(const std::string& a, const std::string& b) {
  char *ea = nullptr, *eb = nullptr;
  const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
  if (!a.empty() && !b.empty() && *ea == '\0' && *eb == '\0') return x == y;
  return a == b;
}

/// Each test renders its own two seconds: ctest runs the tests as separate processes, at once,
/// and a folder shared between them would be removed under the other's feet.
class PaperIni : public ::testing::Test {
 protected:
  void SetUp() override {
    sim_ = dynslam::testing::scratchDir() + "/sim";
    const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                   "/params/sim/indoor_people_high.ini --out " + sim_ +
                                   " --set Scenario.duration=2 --quiet 2>&1");
    ASSERT_EQ(render.exit_code, 0) << render.output;
  }
  std::string dynslam(const std::string& args) const {
    return binDir() + "/dynslam --config " + sourceDir() +
           "/params/paper.ini --set Detection.objects=" + sim_ + "/objects.txt " + args + " 2>&1";
  }
  std::string sim_;
};

}  // namespace

TEST_F(PaperIni, RunsTheWholeSystemOnTwoSimulatedSeconds) {
  const std::string out = sim_ + "/paper";
  const auto run = runCommand(dynslam("--rawlog " + sim_ + "/sim.rawlog --out " + out + " --gt " +
                                      sim_ + "/groundtruth.tum --quiet --no-map"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(dynslam::core::readTum(out + "/trajectory.tum").size(), 61u) << "a pose per frame";
  const std::string summary = readTextFile(out + "/summary.json");
  EXPECT_NE(summary.find("\"status\": \"ok\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"ape\""), std::string::npos) << summary;
}

TEST_F(PaperIni, EveryDepartureIsOnByDefaultAndOffInPaperIni) {
  const auto departures = departuresInDesign();
  ASSERT_GE(departures.size(), 40u) << "design.md's departures table, one key per row";
  const auto defaults = defaultsInReference();
  const auto printed = runCommand(dynslam("--print-config"));
  ASSERT_EQ(printed.exit_code, 0) << printed.output;
  const auto paper = printedConfig(printed.output);
  for (const auto& d : departures) {
    const std::string name = d.section + "." + d.key;
    ASSERT_TRUE(defaults.count(name)) << name << " is not in docs/parameters.md";
    EXPECT_TRUE(sameValue(defaults.at(name), d.shipped))
        << name << ": design.md says the default is " << d.shipped << ", the code "
        << defaults.at(name);
    if (d.paper.empty()) continue;
    ASSERT_TRUE(paper.count(name)) << name << " is not read by paper.ini's stages";
    EXPECT_TRUE(sameValue(paper.at(name), d.paper))
        << name << ": design.md says paper.ini holds " << d.paper << ", it runs " << paper.at(name);
  }
}
