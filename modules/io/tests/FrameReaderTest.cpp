// FrameReader reads on its own thread and must hand out exactly what RawlogSource + SensorSync
// give on one thread, keep their errors (after the frames before them), and stop cleanly when
// its consumer stops early.
#include <dynslam/testing/SyntheticObservations.h>

#include <dynslam/io/FrameReader.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/testing/TestEnv.h>

#include <chrono>
#include <filesystem>
#include <thread>

using namespace dynslam::io;
using namespace dynslam::testing;
namespace fs = std::filesystem;

namespace {

/// 30 camera frames at 30 Hz with IMU samples at 200 Hz between them.
std::vector<mrpt::serialization::CSerializable::Ptr> cameraAndImu() {
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 30; ++i) {
    const double t = 5.0 + i / 30.0;
    for (int k = 0; k < 6; ++k) objs.push_back(makeImu(t + k * 0.005));
    objs.push_back(makeScan(t + 0.001, 160, 120));
  }
  return objs;
}

std::vector<dynslam::core::Frame> readOnOneThread(const std::string& path) {
  RawlogSource source(path);
  SensorSync sync;
  std::vector<dynslam::core::Frame> frames;
  while (const auto obs = source.next()) sync.push(obs, frames);
  sync.flush(frames);
  return frames;
}

}  // namespace

TEST(FrameReader, HandsOutTheFramesOfRawlogSourceAndSensorSyncInOrder) {
  const std::string path = scratchDir() + "/frames.rawlog";
  writeRawlog(path, cameraAndImu());
  const auto expected = readOnOneThread(path);
  ASSERT_EQ(expected.size(), 30u);

  FrameReader reader(path, SensorSyncOptions{}, 2);  // a small queue: the reader waits often
  size_t n = 0;
  while (auto frame = reader.next()) {
    ASSERT_LT(n, expected.size());
    EXPECT_EQ(frame->index, expected[n].index);
    EXPECT_DOUBLE_EQ(frame->t, expected[n].t);
    EXPECT_EQ(frame->imu.size(), expected[n].imu.size()) << "frame " << n;
    EXPECT_EQ(frame->depth.size(), expected[n].depth.size());
    ++n;
  }
  EXPECT_EQ(n, expected.size());
  EXPECT_FALSE(reader.next()) << "stays at the end";
  EXPECT_DOUBLE_EQ(reader.progress(), 1.0);
  EXPECT_EQ(reader.counts().frames, 30u);
  EXPECT_EQ(reader.counts().imu, 180u);
}

TEST(FrameReader, CountsWhatWasReadUpToTheLastFrameHandedOutNotWhatWasReadAhead) {
  const std::string path = scratchDir() + "/counted.rawlog";
  writeRawlog(path, cameraAndImu());
  FrameReader reader(path, SensorSyncOptions{}, 8);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(reader.next());
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // let it read ahead
  EXPECT_EQ(reader.counts().frames, 3u);
  EXPECT_LE(reader.counts().imu, 4u * 6u) << "the IMU samples up to frame 4's camera image";
}

TEST(FrameReader, ATruncatedRawlogIsAnErrorAfterTheFramesBeforeTheCut) {
  const std::string dir = scratchDir();
  const std::string full = dir + "/full.rawlog", cut = dir + "/cut.rawlog";
  writeRawlog(full, cameraAndImu());
  fs::copy_file(full, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(full) / 2);

  FrameReader reader(cut, SensorSyncOptions{}, 4);
  size_t n = 0;
  try {
    while (reader.next()) ++n;
    FAIL() << "reached a clean end in a file cut in half";
  } catch (const RawlogError& e) {
    EXPECT_NE(std::string(e.what()).find(cut), std::string::npos) << e.what();
  }
  EXPECT_GT(n, 5u) << "the frames before the cut are handed out first";
  EXPECT_LT(n, 30u);
}

TEST(FrameReader, AMissingRawlogThrowsAtConstruction) {
  EXPECT_THROW(FrameReader("/no/such/file.rawlog", SensorSyncOptions{}), RawlogError);
}

TEST(FrameReader, StopsWhenItsConsumerStopsEarly) {
  const std::string path = scratchDir() + "/early.rawlog";
  writeRawlog(path, cameraAndImu());
  {
    FrameReader reader(path, SensorSyncOptions{}, 1);
    ASSERT_TRUE(reader.next());
  }  // the reading thread waits for room in its queue: the destructor must release and join it
  SUCCEED();
}
