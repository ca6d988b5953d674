// sevenscenes2rawlog on ../shared/data/7scenes: counts, depth values, external colour images,
// time stamps, ground truth. The 600 frames are converted once per test binary.
#include "RawlogTestSupport.h"

#include <dynslam/testing/TestEnv.h>
#include <gtest/gtest.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using dynslam::rawlog_tools::testing::forEachObservation;
using dynslam::rawlog_tools::testing::program;
using dynslam::rawlog_tools::testing::rawlogEditInfo;
using dynslam::rawlog_tools::testing::shellQuoted;
using dynslam::testing::runCommand;
using mrpt::obs::CObservation3DRangeScan;

namespace {

constexpr double kT0 = 1600000000.0;  // the converter's documented default
constexpr int kFrames = 600;

std::string framePath(const std::string& dir, int index, const char* suffix) {
  char name[64];
  std::snprintf(name, sizeof(name), "frame-%06d.%s", index, suffix);
  return (fs::path(dir) / name).string();
}

Eigen::Matrix4d readMatrix(const std::string& file) {
  std::ifstream in(file);
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> m(r, c);
  return m;
}

/// Holds an exclusive flock on a file for its lifetime (ctest -j runs these tests as parallel
/// processes that share one converted rawlog).
class FileLock {
 public:
  explicit FileLock(const std::string& path) : fd_(::open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

/// Identifies the converter build that produced a cached rawlog.
std::string programSignature(const std::string& programFile, const std::string& dataDir) {
  std::error_code ec;
  const auto size = fs::file_size(programFile, ec);
  const auto mtime = fs::last_write_time(programFile, ec).time_since_epoch().count();
  return programFile + " " + std::to_string(size) + " " + std::to_string(mtime) + " " + dataDir;
}

}  // namespace

class RawlogToolsSevenScenes : public ::testing::Test {
 protected:
  // CTest runs every test of this binary as its own process, so the conversion is cached on
  // disk: converted once per converter build (signature = program size + mtime), reused by
  // the other tests, redone when the program changes.
  static void SetUpTestSuite() {
    dataDir_ = dynslam::testing::sharedPath("data/7scenes");
    if (dataDir_.empty()) return;
    // Beside the other tests' scratch folders (DYNSLAM_TEST_TMP, by default build/test-tmp).
    const char* tmp = std::getenv("DYNSLAM_TEST_TMP");
    const fs::path root = tmp && *tmp
                              ? fs::path(tmp)
                              : fs::path(dynslam::testing::binDir()).parent_path() / "test-tmp";
    const fs::path dir = root / "rawlog_tools_sevenscenes_fixture";
    fs::create_directories(dir);
    rawlog_ = (dir / "seven.rawlog").string();
    FileLock lock((dir / "lock").string());
    const std::string signature = programSignature(
        dynslam::rawlog_tools::testing::programPath("sevenscenes2rawlog"), dataDir_);
    if (dynslam::testing::readTextFile((dir / "signature").string()) == signature &&
        fs::exists(rawlog_)) {
      conversion_.exit_code = 0;
      conversion_.output = dynslam::testing::readTextFile((dir / "output").string());
      seconds_ = std::stod(dynslam::testing::readTextFile((dir / "seconds").string()));
      return;
    }
    fs::remove(dir / "signature");
    fs::remove_all(dir / "seven_Images");
    const auto start = std::chrono::steady_clock::now();
    conversion_ = runCommand(program("sevenscenes2rawlog") + " --in " + shellQuoted(dataDir_) +
                             " --out " + shellQuoted(rawlog_) + " --first 0 --last 599");
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (conversion_.exit_code != 0) return;
    std::ofstream(dir / "output") << conversion_.output;
    std::ofstream(dir / "seconds") << seconds_;
    std::ofstream(dir / "signature") << signature;
  }

  void SetUp() override {
    if (dataDir_.empty())
      GTEST_SKIP() << "needs " << dynslam::testing::sharedDir() << "/data/7scenes, which is absent";
    ASSERT_EQ(conversion_.exit_code, 0) << conversion_.output;
  }

  /// The observations with the given indices (streaming; the others are dropped at once).
  static std::map<int, CObservation3DRangeScan::Ptr> observationsAt(const std::set<int>& wanted) {
    std::map<int, CObservation3DRangeScan::Ptr> found;
    int index = 0;
    forEachObservation(rawlog_, [&](const mrpt::obs::CObservation::Ptr& o) {
      if (wanted.count(index)) found[index] = std::dynamic_pointer_cast<CObservation3DRangeScan>(o);
      ++index;
    });
    return found;
  }

  static inline std::string dataDir_, rawlog_;
  static inline dynslam::testing::CommandResult conversion_;
  static inline double seconds_ = 0;
};

TEST_F(RawlogToolsSevenScenes, ConvertsSixHundredFramesWellUnderAMinute) {
  std::cout << "sevenscenes2rawlog, 600 frames: " << seconds_ << " s, rawlog "
            << fs::file_size(rawlog_) / 1e6 << " MB\n";
  EXPECT_LT(seconds_, 60.0);
  EXPECT_NE(conversion_.output.find("wrote 600 RGBD observations"), std::string::npos)
      << conversion_.output;
}

TEST_F(RawlogToolsSevenScenes, StreamsSixHundredRgbdObservationsThirtiethOfASecondApart) {
  int count = 0;
  double previous = 0;
  forEachObservation(rawlog_, [&](const mrpt::obs::CObservation::Ptr& o) {
    const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o);
    ASSERT_TRUE(obs) << "observation " << count << " is a " << o->GetRuntimeClass()->className;
    EXPECT_EQ(obs->sensorLabel, "RGBD");
    const double t = mrpt::Clock::toDouble(obs->timestamp);
    EXPECT_NEAR(t, kT0 + count / 30.0, 1e-6) << "frame " << count;
    if (count > 0) {
      EXPECT_NEAR(t - previous, 1.0 / 30.0, 1e-6) << "frame " << count;
    }
    previous = t;
    ++count;
  });
  EXPECT_EQ(count, kFrames);
}

// The intrinsics file is the depth camera's; the colour camera has f = 525 px at the same
// principal point, and both sit at the same place (readers register depth to colour).
TEST_F(RawlogToolsSevenScenes, SetsCameraFieldsFromTheIntrinsicsFile) {
  const auto obs = observationsAt({0}).at(0);
  ASSERT_TRUE(obs);
  for (const mrpt::img::TCamera* cam : {&obs->cameraParams, &obs->cameraParamsIntensity}) {
    const double f = cam == &obs->cameraParams ? 585.0 : 525.0;
    EXPECT_EQ(cam->ncols, 640u);
    EXPECT_EQ(cam->nrows, 480u);
    EXPECT_DOUBLE_EQ(cam->fx(), f);
    EXPECT_DOUBLE_EQ(cam->fy(), f);
    EXPECT_DOUBLE_EQ(cam->cx(), 320.0);
    EXPECT_DOUBLE_EQ(cam->cy(), 240.0);
  }
  EXPECT_TRUE(obs->hasRangeImage);
  EXPECT_TRUE(obs->hasIntensityImage);
  EXPECT_TRUE(obs->range_is_depth);
  EXPECT_FLOAT_EQ(obs->rangeUnits, 0.001f);
  EXPECT_TRUE(obs->doDepthAndIntensityCamerasCoincide());
}

TEST_F(RawlogToolsSevenScenes, DepthEqualsPngMillimetresWithInvalidAsZero) {
  // The first frame holding a 65535 (invalid) pixel joins the sampled frames (frame 33 of the
  // shared sequence; searched rather than hard-coded).
  int invalidFrame = -1;
  cv::Point invalidPixel;
  for (int i = 0; i < kFrames && invalidFrame < 0; ++i) {
    const cv::Mat png = cv::imread(framePath(dataDir_, i, "depth.png"), cv::IMREAD_UNCHANGED);
    std::vector<cv::Point> where;
    cv::findNonZero(png == 65535, where);
    if (!where.empty()) {
      invalidFrame = i;
      invalidPixel = where.front();
    }
  }
  std::set<int> frames = {0, 1, 257, 598, 599};
  if (invalidFrame >= 0) frames.insert(invalidFrame);
  const auto observations = observationsAt(frames);
  ASSERT_EQ(observations.size(), frames.size());
  size_t invalidPixelsSeen = 0, zeroPixelsSeen = 0;
  for (const auto& [index, obs] : observations) {
    ASSERT_TRUE(obs);
    const cv::Mat png = cv::imread(framePath(dataDir_, index, "depth.png"), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(png.type(), CV_16UC1);
    ASSERT_EQ(obs->rangeImage.rows(), png.rows);
    ASSERT_EQ(obs->rangeImage.cols(), png.cols);
    size_t mismatches = 0;
    for (int r = 0; r < png.rows; ++r)
      for (int c = 0; c < png.cols; ++c) {
        const uint16_t raw = png.at<uint16_t>(r, c);
        const double expectedMetres = raw == 65535 ? 0.0 : raw / 1000.0;
        invalidPixelsSeen += raw == 65535;
        zeroPixelsSeen += raw == 0;
        const double metres = obs->rangeImage(r, c) * obs->rangeUnits;
        if (std::abs(metres - expectedMetres) > 1e-6) ++mismatches;
      }
    EXPECT_EQ(mismatches, 0u) << "frame " << index;
    // A few named pixels, so a failure shows values and not only a count.
    for (const auto& [r, c] : {std::pair{240, 320}, std::pair{100, 500}, std::pair{479, 639}}) {
      const uint16_t raw = png.at<uint16_t>(r, c);
      EXPECT_NEAR(obs->rangeImage(r, c) * obs->rangeUnits, raw == 65535 ? 0.0 : raw / 1000.0, 1e-6)
          << "frame " << index << " pixel (" << r << ", " << c << "), png " << raw;
    }
  }
  EXPECT_EQ(observations.at(0)->rangeImage(240, 320), 1382);  // 1.382 m in frame-000000.depth.png
  if (invalidFrame >= 0) {
    EXPECT_GT(invalidPixelsSeen, 0u);
    EXPECT_EQ(observations.at(invalidFrame)->rangeImage(invalidPixel.y, invalidPixel.x), 0)
        << "frame " << invalidFrame << " pixel " << invalidPixel;
  }
  std::cout << "sampled frames: " << invalidPixelsSeen << " invalid (65535) pixels, first in frame "
            << invalidFrame << "; " << zeroPixelsSeen << " zero pixels\n";
}

TEST_F(RawlogToolsSevenScenes, ColourLoadsFromExternalStorageAndEqualsTheJpeg) {
  const auto observations = observationsAt({0, 300, 599});
  for (const auto& [index, obs] : observations) {
    ASSERT_TRUE(obs);
    ASSERT_TRUE(obs->intensityImage.isExternallyStored()) << "frame " << index;
    const fs::path stored = fs::path(rawlog_).parent_path() / "seven_Images" /
                            obs->intensityImage.getExternalStorageFile();
    EXPECT_TRUE(fs::exists(stored)) << stored;
    obs->load();
    const cv::Mat decoded = obs->intensityImage.asCvMatRef();
    const cv::Mat jpeg = cv::imread(framePath(dataDir_, index, "color.jpg"), cv::IMREAD_COLOR);
    ASSERT_EQ(decoded.size(), jpeg.size()) << "frame " << index;
    ASSERT_EQ(decoded.type(), jpeg.type());
    EXPECT_EQ(cv::norm(decoded, jpeg, cv::NORM_INF), 0.0) << "frame " << index;
    obs->unload();
  }
}

TEST_F(RawlogToolsSevenScenes, RawlogEditInfoCountsSixHundredRgbd) {
  const auto info = rawlogEditInfo(rawlog_);
  if (!info.available) GTEST_SKIP() << "rawlog-edit (mrpt-apps) is not installed";
  ASSERT_EQ(info.exitCode, 0) << info.output;
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(info.output, m, std::regex(R"(Overall number of objects\s*:\s*(\d+))")))
      << info.output;
  EXPECT_EQ(std::stoi(m[1].str()), kFrames);
  ASSERT_TRUE(std::regex_search(info.output, m, std::regex(R"(RGBD\s*/\s*(\d+))"))) << info.output;
  EXPECT_EQ(std::stoi(m[1].str()), kFrames);
  EXPECT_NE(info.output.find("Found external storage directory: seven_Images"), std::string::npos)
      << info.output;
}

TEST_F(RawlogToolsSevenScenes, GroundTruthHasOnePoseFileLinePerFrame) {
  std::ifstream in(fs::path(rawlog_).replace_extension(".gt.tum"));
  ASSERT_TRUE(in);
  int index = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double t, x, y, z, qx, qy, qz, qw;
    ASSERT_TRUE(fields >> t >> x >> y >> z >> qx >> qy >> qz >> qw) << line;
    ASSERT_LT(index, kFrames);
    EXPECT_NEAR(t, kT0 + index / 30.0, 1e-6);
    const Eigen::Matrix4d expected = readMatrix(framePath(dataDir_, index, "pose.txt"));
    EXPECT_NEAR(x, expected(0, 3), 1e-9);
    EXPECT_NEAR(y, expected(1, 3), 1e-9);
    EXPECT_NEAR(z, expected(2, 3), 1e-9);
    // The files' rotations are orthonormal only to ~3e-4; the converter projects them onto
    // SO(3), so entries agree to that level.
    const Eigen::Matrix3d rotation =
        Eigen::Quaterniond(qw, qx, qy, qz).normalized().toRotationMatrix();
    EXPECT_LT((rotation - expected.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff(), 1e-3)
        << "frame " << index;
    ++index;
  }
  EXPECT_EQ(index, kFrames);
}

TEST_F(RawlogToolsSevenScenes, GroundTruthEvaluatesAgainstItselfWithZeroApe) {
  const std::string gt = fs::path(rawlog_).replace_extension(".gt.tum").string();
  const auto r = runCommand(program("dynslam-eval") + " ape " + shellQuoted(gt) + " " +
                            shellQuoted(gt) + " --align se3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("pairs       600 of max. 600"), std::string::npos) << r.output;
  std::istringstream lines(r.output);
  double rmse = -1;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("rmse", 0) == 0) rmse = std::stod(line.substr(4));
  EXPECT_GE(rmse, 0.0) << r.output;
  EXPECT_LT(rmse, 1e-9) << r.output;
}

TEST(RawlogToolsSevenScenesConverter, FrameRangeAndEmbeddedImages) {
  DYNSLAM_REQUIRE_SHARED(dataDir, "data/7scenes");
  const std::string rawlog = dynslam::testing::scratchDir() + "/range.rawlog";
  const auto r =
      runCommand(program("sevenscenes2rawlog") + " --embed-images --in " + shellQuoted(dataDir) +
                 " --out " + shellQuoted(rawlog) + " --first 10 --last 12");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(fs::path(rawlog).parent_path() / "range_Images"));
  int index = 10;
  forEachObservation(rawlog, [&](const mrpt::obs::CObservation::Ptr& o) {
    const auto obs = std::dynamic_pointer_cast<CObservation3DRangeScan>(o);
    ASSERT_TRUE(obs);
    EXPECT_NEAR(mrpt::Clock::toDouble(obs->timestamp), kT0 + index / 30.0, 1e-6);
    EXPECT_FALSE(obs->intensityImage.isExternallyStored());
    const cv::Mat jpeg = cv::imread(framePath(dataDir, index, "color.jpg"), cv::IMREAD_COLOR);
    EXPECT_EQ(cv::norm(obs->intensityImage.asCvMatRef(), jpeg, cv::NORM_INF), 0.0);
    ++index;
  });
  EXPECT_EQ(index, 13);
}

// --colour-intrinsics: "depth" writes the depth camera's for colour too (the cameras then
// coincide for readers), explicit values are written as given, malformed ones are an error
// naming the flag.
TEST(RawlogToolsSevenScenesConverter, ColourIntrinsicsFlag) {
  DYNSLAM_REQUIRE_SHARED(dataDir, "data/7scenes");
  const std::string rawlog = dynslam::testing::scratchDir() + "/colourk.rawlog";
  const auto convert = [&](const std::string& value) {
    return runCommand(program("sevenscenes2rawlog") + " --embed-images --in " +
                      shellQuoted(dataDir) + " --out " + shellQuoted(rawlog) +
                      " --first 0 --last 0 --colour-intrinsics " + value);
  };
  const auto colourCamera = [&] {
    mrpt::img::TCamera cam;
    forEachObservation(rawlog, [&](const mrpt::obs::CObservation::Ptr& o) {
      cam = std::dynamic_pointer_cast<CObservation3DRangeScan>(o)->cameraParamsIntensity;
    });
    return cam;
  };
  auto r = convert("depth");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_DOUBLE_EQ(colourCamera().fx(), 585.0);
  r = convert("520,521,319,241");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto cam = colourCamera();
  EXPECT_DOUBLE_EQ(cam.fx(), 520.0);
  EXPECT_DOUBLE_EQ(cam.fy(), 521.0);
  EXPECT_DOUBLE_EQ(cam.cx(), 319.0);
  EXPECT_DOUBLE_EQ(cam.cy(), 241.0);
  for (const std::string bad : {"525,525", "525,525,320,abc", "0,525,320,240"}) {
    r = convert(bad);
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_NE(r.output.find("--colour-intrinsics"), std::string::npos) << r.output;
  }
}

TEST(RawlogToolsSevenScenesConverter, MissingInputFolderIsAnErrorNamingIt) {
  const std::string out = dynslam::testing::scratchDir() + "/x.rawlog";
  const auto r = runCommand(program("sevenscenes2rawlog") + " --in /nonexistent/7scenes --out " +
                            shellQuoted(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("/nonexistent/7scenes"), std::string::npos) << r.output;
  const auto help = runCommand(program("sevenscenes2rawlog") + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--first"), std::string::npos);
}
