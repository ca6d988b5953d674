#include <dynslam/testing/SyntheticObservations.h>

#include <dynslam/io/RawlogSource.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <filesystem>
#include <fstream>

using namespace dynslam::io;
using namespace dynslam::testing;
namespace fs = std::filesystem;

TEST(RawlogSource, StreamsObservationFormatInOrder) {
  const std::string path = dynslam::testing::scratchDir() + "/obs.rawlog";
  writeRawlog(path, {makeImu(1.00), makeScan(1.01), makeImu(1.02), makeScan(1.05)});
  RawlogSource src(path);
  std::vector<std::string> classes;
  std::vector<double> stamps;
  while (auto obs = src.next()) {
    classes.push_back(obs->GetRuntimeClass()->className);
    stamps.push_back(mrpt::Clock::toDouble(obs->timestamp));
  }
  ASSERT_EQ(classes.size(), 4u);
  EXPECT_EQ(classes[0], "mrpt::obs::CObservationIMU");
  EXPECT_EQ(classes[1], "mrpt::obs::CObservation3DRangeScan");
  EXPECT_NEAR(stamps[3], 1.05, 1e-6);
  EXPECT_EQ(src.entriesRead(), 4u);
  EXPECT_DOUBLE_EQ(src.progress(), 1.0);
  EXPECT_EQ(src.next(), nullptr) << "stays at the end";
}

TEST(RawlogSource, StreamsSensoryFrameFormatAndSkipsActions) {
  const std::string path = dynslam::testing::scratchDir() + "/sf.rawlog";
  auto acts = mrpt::obs::CActionCollection::Create();
  mrpt::obs::CActionRobotMovement2D odo;
  acts->insert(odo);
  auto sf1 = mrpt::obs::CSensoryFrame::Create();
  sf1->insert(makeImu(2.0));
  sf1->insert(makeScan(2.01));
  auto sf2 = mrpt::obs::CSensoryFrame::Create();
  sf2->insert(makeScan(2.05));
  writeRawlog(path, {acts, sf1, acts, sf2});
  RawlogSource src(path);
  size_t n = 0;
  while (src.next()) ++n;
  EXPECT_EQ(n, 3u);
  EXPECT_EQ(src.entriesRead(), 4u);
}

TEST(RawlogSource, TruncatedFileIsAnErrorAfterTheIntactEntries) {
  const std::string dir = dynslam::testing::scratchDir();
  const std::string full = dir + "/full.rawlog", cut = dir + "/cut.rawlog";
  std::vector<mrpt::serialization::CSerializable::Ptr> objs;
  for (int i = 0; i < 20; ++i) objs.push_back(makeScan(10 + i * 0.033, 160, 120));
  writeRawlog(full, objs);
  const auto size = fs::file_size(full);
  fs::copy_file(full, cut);
  fs::resize_file(cut, size / 2);

  RawlogSource src(cut);
  size_t n = 0;
  try {
    while (src.next()) ++n;
    FAIL() << "reached a clean end in a file cut in half";
  } catch (const RawlogError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(cut), std::string::npos) << msg;
    EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
  }
  EXPECT_GT(n, 3u) << "the intact entries before the cut are delivered";
  EXPECT_LT(n, 20u);
}

// An entry of a class MRPT does not know (a flipped bit in its name): the error says what MRPT
// says, in one line, without MRPT's banner and backtrace.
TEST(RawlogSource, AnUnknownClassIsAnErrorInOneReadableLine) {
  const std::string path = dynslam::testing::scratchDir() + "/renamed.rawlog";
  {
    mrpt::io::CFileOutputStream f(path);  // plain: the class names are in the bytes
    auto out = mrpt::serialization::archiveFrom(f);
    out << *makeImu(1.0) << *makeImu(1.005);
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = bytes.rfind("CObservationIMU");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 14] = 'X';
  std::ofstream(path, std::ios::binary) << bytes;
  RawlogSource src(path);
  ASSERT_TRUE(src.next());
  try {
    src.next();
    FAIL() << "no error for an unknown class";
  } catch (const RawlogError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find("CObservationIMX"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("===="), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(RawlogSource, MissingFileNamesIt) {
  try {
    RawlogSource src("/no/such/file.rawlog");
    FAIL();
  } catch (const RawlogError& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/file.rawlog"), std::string::npos);
  }
}

TEST(RawlogSource, TextFileIsNotARawlog) {
  const std::string path = dynslam::testing::scratchDir() + "/notes.rawlog";
  std::ofstream(path) << "this is not a rawlog, just some words in a text file\n";
  RawlogSource src(path);
  EXPECT_THROW(src.next(), RawlogError);
}

TEST(RawlogSource, FindsExternallyStoredImages) {
  const std::string dir = dynslam::testing::scratchDir();
  fs::create_directories(dir + "/ext_Images");
  auto scan = makeScan(3.0);
  scan->intensityImage.saveToFile(dir + "/ext_Images/img0.png");
  scan->intensityImage.setExternalStorage("img0.png");
  writeRawlog(dir + "/ext.rawlog", {scan});
  RawlogSource src(dir + "/ext.rawlog");
  EXPECT_EQ(src.imagesDir(), dir + "/ext_Images");
  auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(src.next());
  ASSERT_TRUE(obs);
  EXPECT_TRUE(obs->intensityImage.isExternallyStored());
  obs->load();
  EXPECT_EQ(obs->intensityImage.getWidth(), 64u);
}
