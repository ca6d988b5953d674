// The dynslam-eval program end to end: evo's KITTI_00 figures through the command line, the
// JSON file, the PNG plot, and its error handling (exit code 2 for usage, 1 for bad data).
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace dt = dynslam::testing;
namespace fs = std::filesystem;

namespace {

std::string program() { return dt::binDir() + "/dynslam-eval"; }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

/// The members of a flat JSON object of numbers, in file order.
std::vector<std::pair<std::string, double>> parseFlatJson(const std::string& text) {
  std::vector<std::pair<std::string, double>> members;
  const std::regex member(R"re("([^"]+)"\s*:\s*([-+0-9.eE]+))re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), member);
       it != std::sregex_iterator(); ++it)
    members.emplace_back((*it)[1].str(), std::stod((*it)[2].str()));
  return members;
}

void expectEvoFigures(const std::vector<std::pair<std::string, double>>& members,
                      const std::map<std::string, double>& evo) {
  ASSERT_EQ(members.size(), 7u);
  const char* order[] = {"rmse", "mean", "median", "std", "min", "max", "sse"};
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_EQ(members[k].first, order[k]);
    const double expected = evo.at(members[k].first);
    EXPECT_LE(std::abs(members[k].second - expected), 1e-6 * std::abs(expected))
        << members[k].first;
  }
}

}  // namespace

TEST(EvalCli, KittiApeWithJsonAndPlot) {
  DYNSLAM_REQUIRE_SHARED(gt, "data/evo/KITTI_00_gt.txt");
  DYNSLAM_REQUIRE_SHARED(orb, "data/evo/KITTI_00_ORB.txt");
  const std::string dir = dt::scratchDir();
  const std::string json = dir + "/ape.json", png = dir + "/ape.png";
  const auto r = dt::runCommand(program() + " ape " + quoted(gt) + " " + quoted(orb) +
                                " --format kitti --align se3 --json " + quoted(json) + " --plot " +
                                quoted(png));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pairs       4541"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rmse   1.30344971456"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("scale       1\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rotation    0.99983853"), std::string::npos) << r.output;

  expectEvoFigures(parseFlatJson(dt::readTextFile(json)), {{"rmse", 1.3034497145650266},
                                                           {"mean", 1.1569971285389768},
                                                           {"median", 1.065624769555848},
                                                           {"std", 0.6002822693968323},
                                                           {"min", 0.06931322021483087},
                                                           {"max", 3.587949120678954},
                                                           {"sse", 7715.073440292808}});

  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 20000u);
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 1000);
  EXPECT_EQ(img.rows, 1100);
  // Non-trivial: a good share of the pixels is drawn, and both path colours are present.
  cv::Mat gray;
  cv::extractChannel(img, gray, 1);
  EXPECT_GT(cv::countNonZero(gray < 250), img.total() / 50);
  cv::Mat blue, grey;
  cv::inRange(img, cv::Scalar(180, 90, 0), cv::Scalar(220, 130, 40), blue);
  cv::inRange(img, cv::Scalar(70, 70, 70), cv::Scalar(90, 90, 90), grey);
  EXPECT_GT(cv::countNonZero(blue), 1000);
  EXPECT_GT(cv::countNonZero(grey), 1000);
}

TEST(EvalCli, KittiRpeTenMetres) {
  DYNSLAM_REQUIRE_SHARED(gt, "data/evo/KITTI_00_gt.txt");
  DYNSLAM_REQUIRE_SHARED(orb, "data/evo/KITTI_00_ORB.txt");
  const std::string json = dt::scratchDir() + "/rpe.json";
  const auto r = dt::runCommand(program() + " rpe " + quoted(gt) + " " + quoted(orb) +
                                " --format kitti --delta 10 --delta-unit m --json " + quoted(json));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rpe pairs   353"), std::string::npos) << r.output;
  expectEvoFigures(parseFlatJson(dt::readTextFile(json)), {{"rmse", 0.22626134329310163},
                                                           {"mean", 0.16901737200653275},
                                                           {"median", 0.13848432516645606},
                                                           {"std", 0.1504238127053164},
                                                           {"min", 0.025322719660754993},
                                                           {"max", 1.2722090778658726},
                                                           {"sse", 18.07155100048597}});
}

TEST(EvalCli, EurocReferenceWithTumEstimate) {
  DYNSLAM_REQUIRE_SHARED(gt, "data/evo/V102_groundtruth.csv");
  DYNSLAM_REQUIRE_SHARED(est, "data/evo/V102.txt");
  const auto r = dt::runCommand(program() + " ape " + quoted(gt) + " " + quoted(est) +
                                " --ref-format euroc --align sim3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pairs       798 of max. 807"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("scale       0.97969825"), std::string::npos) << r.output;
}

TEST(EvalCli, HelpAndUsageErrors) {
  const auto help = dt::runCommand(program() + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("dynslam-eval ape REF EST"), std::string::npos) << help.output;

  const auto no_args = dt::runCommand(program());
  EXPECT_EQ(no_args.exit_code, 2) << no_args.output;

  const auto bad_flag = dt::runCommand(program() + " ape a.txt b.txt --allign se3");
  EXPECT_EQ(bad_flag.exit_code, 2);
  EXPECT_NE(bad_flag.output.find("--allign"), std::string::npos) << bad_flag.output;

  const auto bad_value = dt::runCommand(program() + " ape a.txt b.txt --align se2");
  EXPECT_EQ(bad_value.exit_code, 2);
  EXPECT_NE(bad_value.output.find("--align"), std::string::npos) << bad_value.output;

  const auto bad_number = dt::runCommand(program() + " ape a.txt b.txt --t-max-diff 1x");
  EXPECT_EQ(bad_number.exit_code, 2);
  EXPECT_NE(bad_number.output.find("--t-max-diff"), std::string::npos) << bad_number.output;

  const auto rpe_flag_on_ape = dt::runCommand(program() + " ape a.txt b.txt --delta 3");
  EXPECT_EQ(rpe_flag_on_ape.exit_code, 2);
  EXPECT_NE(rpe_flag_on_ape.output.find("--delta"), std::string::npos) << rpe_flag_on_ape.output;
}

TEST(EvalCli, BadDataNamesFileAndLine) {
  const std::string dir = dt::scratchDir();
  const std::string good = dir + "/good.txt", bad = dir + "/bad.txt";
  std::ofstream(good) << "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n";
  std::ofstream(bad) << "# comment\n0 0 0 0 0 0 0 1\n1 1 0 0 zero 0 0 1\n";
  const auto r = dt::runCommand(program() + " ape " + quoted(good) + " " + quoted(bad));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(bad + ":3:"), std::string::npos) << r.output;

  const auto missing =
      dt::runCommand(program() + " ape " + quoted(good) + " " + quoted(dir + "/missing.txt"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.output.find(dir + "/missing.txt"), std::string::npos) << missing.output;

  // No common timestamps: bad data, not bad usage.
  const std::string late = dir + "/late.txt";
  std::ofstream(late) << "100 0 0 0 0 0 0 1\n101 1 0 0 0 0 0 1\n";
  const auto apart = dt::runCommand(program() + " ape " + quoted(good) + " " + quoted(late));
  EXPECT_EQ(apart.exit_code, 1);
  EXPECT_NE(apart.output.find("no matching timestamps"), std::string::npos) << apart.output;

  // KITTI files of different length cannot be paired by index.
  const std::string k1 = dir + "/k1.txt", k2 = dir + "/k2.txt";
  std::ofstream(k1) << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n";
  std::ofstream(k2) << "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const auto lengths =
      dt::runCommand(program() + " ape " + quoted(k1) + " " + quoted(k2) + " --format kitti");
  EXPECT_EQ(lengths.exit_code, 1);
  EXPECT_NE(lengths.output.find("same number of poses (2 vs 1)"), std::string::npos)
      << lengths.output;
}

TEST(EvalCli, BarsDrawsATableAndNamesItsBadLines) {
  const std::string dir = dt::scratchDir();
  const std::string table = dir + "/ape.tsv", png = dir + "/bars.png";
  std::ofstream(table) << "# APE RMSE\nscenario\tnone\tremove\tfull\n"
                       << "indoor_people_high\t0.3562\t0.02347\t0.02357\n"
                       << "augmented_7scenes\t0.1697\t-\t0.08087\n";
  const auto r = dt::runCommand(program() + " bars " + quoted(table) + " " + quoted(png) +
                                " --title 'APE RMSE' --value-label 'APE RMSE (m)'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 groups x 3 series"), std::string::npos) << r.output;
  const cv::Mat img = cv::imread(png, cv::IMREAD_COLOR);
  EXPECT_FALSE(img.empty());

  std::ofstream(dir + "/bad.tsv") << "scenario\tnone\tfull\nroom\t0.1\tzero\n";
  const auto bad =
      dt::runCommand(program() + " bars " + quoted(dir + "/bad.tsv") + " " + quoted(png));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find(dir + "/bad.tsv:2: 'zero' is not a number"), std::string::npos)
      << bad.output;

  const auto ape_flag =
      dt::runCommand(program() + " bars " + quoted(table) + " " + quoted(png) + " --align se3");
  EXPECT_EQ(ape_flag.exit_code, 2);
  EXPECT_NE(ape_flag.output.find("--align only applies to ape and rpe"), std::string::npos)
      << ape_flag.output;
}
