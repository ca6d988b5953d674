// A rawlog whose size fields claim a huge image, point count or string is refused before MRPT
// allocates it; valid rawlogs read as before. The corrupt files are real MRPT streams with the
// size field's bytes overwritten.
#include <dynslam/testing/SyntheticObservations.h>

#include "../src/SerializedSizeGuard.h"

#include <dynslam/io/RawlogSource.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace dynslam::io;
using namespace dynslam::testing;
using Bytes = std::vector<uint8_t>;
using mrpt::obs::CObservation3DRangeScan;

namespace {

Bytes bytesOf(const mrpt::serialization::CSerializable& o) {
  mrpt::io::CMemoryStream m;
  auto out = mrpt::serialization::archiveFrom(m);
  out << o;
  const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
  return Bytes(p, p + m.getTotalBytesCount());
}

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes all;
  for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

void writeBytes(const std::string& path, const Bytes& b) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), b.size());
}

/// Offset of the first two consecutive little-endian uint32 equal to (a, b).
size_t findPair(const Bytes& b, uint32_t a, uint32_t c) {
  for (size_t i = 0; i + 8 <= b.size(); ++i) {
    uint32_t x, y;
    std::memcpy(&x, &b[i], 4);
    std::memcpy(&y, &b[i + 4], 4);
    if (x == a && y == c) return i;
  }
  ADD_FAILURE() << "pattern not found";
  return 0;
}

void put32(Bytes& b, size_t at, uint32_t v) { std::memcpy(&b[at], &v, 4); }

long peakRssMb() {
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return r.ru_maxrss / 1024;
}

CObservation3DRangeScan::Ptr scanWithPoints(double t, int w, int h, size_t n) {
  auto scan = makeScan(t, w, h);
  scan->hasPoints3D = true;
  scan->resizePoints3DVectors(n);
  for (size_t i = 0; i < n; ++i) scan->points3D_x[i] = 0.001f * static_cast<float>(i);
  return scan;
}

struct ReadOutcome {
  std::string error;  // "" when the file read to its end
  size_t delivered = 0;
  long rss_growth_mb = 0;
};

ReadOutcome readAll(const std::string& path, size_t limit = kDefaultMaxObservationFieldBytes) {
  ReadOutcome r;
  const long before = peakRssMb();
  try {
    RawlogSource src(path, limit);
    while (src.next()) ++r.delivered;
  } catch (const RawlogError& e) {
    r.error = e.what();
  }
  r.rss_growth_mb = peakRssMb() - before;
  return r;
}

/// An IMU entry, the corrupt entry, another IMU entry: the refusal must name entry #1.
ReadOutcome readCorrupt(const std::string& name, const Bytes& corrupt) {
  const std::string path = scratchDir() + "/" + name;
  writeBytes(path, concat({bytesOf(*makeImu(0.9)), corrupt, bytesOf(*makeImu(1.1))}));
  auto r = readAll(path);
  std::cout << "[ peak RSS ] " << name << ": " << peakRssMb() << " MB (+" << r.rss_growth_mb
            << " MB while reading)\n";
  EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("entry #1"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("over the 512 MB limit"), std::string::npos) << r.error;
  EXPECT_EQ(r.delivered, 1u) << "the entry before the corrupt one is delivered";
  EXPECT_LT(r.rss_growth_mb, 200);
  return r;
}

/// Feeds an object's stream to the guard in chunks of `chunk` bytes: true when the guard
/// modelled every field and reached the end byte with the last chunk, not before.
bool guardFollows(const Bytes& b, size_t chunk) {
  detail::SerializedSizeGuard guard(kDefaultMaxObservationFieldBytes);
  guard.beginObject();
  bool early = false;
  for (size_t i = 0; i < b.size(); i += chunk) {
    early = early || guard.followedToEnd();
    guard.observe(b.data() + i, std::min(chunk, b.size() - i));
  }
  return !early && guard.followedToEnd();
}

std::vector<mrpt::serialization::CSerializable::Ptr> validObservations(const std::string& dir) {
  std::filesystem::create_directories(dir + "/valid_Images");
  auto external = makeScan(2.0, 64, 48);
  external->intensityImage.saveToFile(dir + "/valid_Images/img0.png");
  external->intensityImage.setExternalStorage("img0.png");
  auto layered = makeScan(2.1, 64, 48);
  layered->rangeImageOtherLayers["LAST"] = layered->rangeImage;
  layered->hasConfidenceImage = true;
  layered->confidenceImage.resize(64, 48, mrpt::img::CH_GRAY);
  auto grey = mrpt::obs::CObservationImage::Create();
  grey->image.resize(320, 240, mrpt::img::CH_GRAY, mrpt::img::PixelDepth::D16U);
  grey->sensorLabel = "CAM";
  auto colour = mrpt::obs::CObservationImage::Create();
  colour->image = makeScan(2.3, 160, 120)->intensityImage;
  return {makeImu(1.0),
          makeGga(1.0, 40.0, -3.0, 650.0),
          scanWithPoints(1.5, 640, 480, 640 * 480),
          external,
          layered,
          grey,
          colour};
}

/// Runs `write` with colour images stored as JPEG (MRPT's default is raw), then restores it.
template <typename F>
void asJpeg(F&& write) {
  mrpt::img::CImage::DISABLE_JPEG_COMPRESSION(false);
  write();
  mrpt::img::CImage::DISABLE_JPEG_COMPRESSION(true);
}

/// Width x height of each image an observation holds, and its point count, to compare reads.
std::string shape(const mrpt::obs::CObservation& o) {
  std::string s = o.GetRuntimeClass()->className;
  auto size = [](const mrpt::img::CImage& im) {
    return im.isExternallyStored()
               ? std::string(" external")
               : " " + std::to_string(im.getWidth()) + "x" + std::to_string(im.getHeight());
  };
  if (const auto* scan = dynamic_cast<const CObservation3DRangeScan*>(&o))
    s += " " + std::to_string(scan->rangeImage.cols()) + "x" +
         std::to_string(scan->rangeImage.rows()) + size(scan->intensityImage) + " points " +
         std::to_string(scan->points3D_x.size()) + " layers " +
         std::to_string(scan->rangeImageOtherLayers.size());
  if (const auto* img = dynamic_cast<const mrpt::obs::CObservationImage*>(&o))
    s += size(img->image);
  return s + " " + o.sensorLabel;
}

}  // namespace

TEST(SerializedSizeGuard, RefusesAHugeDepthImage) {
  Bytes b = bytesOf(*makeScan(1.0, 64, 48));
  const size_t at = findPair(b, 48, 64);  // rangeImage rows, cols
  put32(b, at, 65536);
  put32(b, at + 4, 65536);
  const auto r = readCorrupt("depth.rawlog", b);
  EXPECT_NE(r.error.find("a CObservation3DRangeScan claims a 65536 x 65536 range image (8 GB)"),
            std::string::npos)
      << r.error;
}

TEST(SerializedSizeGuard, RefusesAHugePointCount) {
  const Bytes five = bytesOf(*scanWithPoints(1.0, 64, 48, 5));
  Bytes b = five;
  const Bytes seven = bytesOf(*scanWithPoints(1.0, 64, 48, 7));
  const auto at = static_cast<size_t>(std::mismatch(five.begin(), five.end(), seven.begin()).first -
                                      five.begin());
  put32(b, at, 0xF0000000u);
  const auto r = readCorrupt("points.rawlog", b);
  EXPECT_NE(r.error.find("claims 4026531840 3D points (60 GB)"), std::string::npos) << r.error;
}

TEST(SerializedSizeGuard, RefusesAHugeRawColourImage) {
  Bytes b = bytesOf(*makeScan(1.0, 64, 48));
  const size_t at = findPair(b, static_cast<uint32_t>(-64), static_cast<uint32_t>(-48));
  put32(b, at, static_cast<uint32_t>(-60000));
  put32(b, at + 4, static_cast<uint32_t>(-60000));
  const auto r = readCorrupt("colour.rawlog", b);
  EXPECT_NE(r.error.find("60000 x 60000 colour image for intensityImage (10.1 GB)"),
            std::string::npos)
      << r.error;
}

TEST(SerializedSizeGuard, RefusesAHugeJpegAndAHugeJpegImageSize) {
  Bytes jpeg;
  asJpeg([&] { jpeg = bytesOf(*makeScan(1.0, 64, 48)); });
  const size_t at = findPair(jpeg, 64, 48);  // colour width, height, then the JPEG's length
  Bytes big_jpeg = jpeg, big_image = jpeg;
  put32(big_jpeg, at + 8, 0xF0000000u);
  put32(big_image, at, 60000);
  put32(big_image, at + 4, 60000);
  EXPECT_NE(readCorrupt("jpeg.rawlog", big_jpeg).error.find("4026531840-byte JPEG"),
            std::string::npos);
  EXPECT_NE(readCorrupt("jpeg_size.rawlog", big_image).error.find("60000 x 60000 colour image"),
            std::string::npos);
}

TEST(SerializedSizeGuard, RefusesAHugeSensorLabel) {
  Bytes b = bytesOf(*makeScan(1.0, 64, 48));
  const Bytes label = {4, 0, 0, 0, 'R', 'G', 'B', 'D'};
  const auto it = std::search(b.begin(), b.end(), label.begin(), label.end());
  ASSERT_NE(it, b.end());
  put32(b, static_cast<size_t>(it - b.begin()), 0xFFFFFFFFu);
  const auto r = readCorrupt("label.rawlog", b);
  EXPECT_NE(r.error.find("claims a 4294967295-byte sensorLabel string (4.0 GB)"), std::string::npos)
      << r.error;
}

TEST(SerializedSizeGuard, RefusesAHugeSensoryFrameCount) {
  auto sf = mrpt::obs::CSensoryFrame::Create();
  sf->insert(makeImu(1.0));
  Bytes b = bytesOf(*sf);
  const Bytes imu_header = {0x80 | 26};  // the IMU's class name length follows the count
  const auto it = std::search(b.begin(), b.end(), imu_header.begin(), imu_header.end());
  ASSERT_NE(it, b.end());
  put32(b, static_cast<size_t>(it - b.begin()) - 4, 0xF0000000u);
  const auto r = readCorrupt("sf.rawlog", b);
  EXPECT_NE(r.error.find("a CSensoryFrame claims 4026531840 observations"), std::string::npos)
      << r.error;
}

TEST(SerializedSizeGuard, ASmallLimitRefusesANormalObservationAndNamesIt) {
  const std::string dir = scratchDir();
  const std::string path = dir + "/vga.rawlog";
  writeRawlog(path, {makeImu(0.9), scanWithPoints(1.0, 640, 480, 640 * 480)});
  const auto r = readAll(path, 1 << 20);
  EXPECT_EQ(r.delivered, 1u);
  EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("claims 307200 3D points (4.7 MB), over the 1 MB limit"),
            std::string::npos)
      << r.error;
  const std::string no_points = dir + "/vga_depth.rawlog";
  writeRawlog(no_points, {makeScan(1.0, 640, 480)});
  const auto depth = readAll(no_points, 500 << 10);
  EXPECT_NE(depth.error.find("a 480 x 640 range image (600 KB), over the 500 KB limit"),
            std::string::npos)
      << depth.error;
}

TEST(SerializedSizeGuard, UnmodelledClassesMeetOnlyThePerReadLimit) {
  mrpt::obs::CObservation2DRangeScan laser;
  laser.resizeScan(1000);
  const std::string path = scratchDir() + "/laser.rawlog";
  writeRawlog(path, {makeImu(0.9), std::make_shared<mrpt::obs::CObservation2DRangeScan>(laser)});
  EXPECT_EQ(readAll(path).error, "") << "read with the default limit";
  const auto r = readAll(path, 2000);
  EXPECT_NE(r.error.find("a read of 4000 bytes"), std::string::npos) << r.error;
  EXPECT_FALSE(guardFollows(bytesOf(laser), 1));
}

TEST(SerializedSizeGuard, ValidRawlogsReadBackFullyAndIdentically) {
  const std::string dir = scratchDir();
  const auto objs = validObservations(dir);
  auto sf = mrpt::obs::CSensoryFrame::Create();
  for (const auto& o : objs) sf->insert(std::dynamic_pointer_cast<mrpt::obs::CObservation>(o));
  writeRawlog(dir + "/valid.rawlog", objs);
  asJpeg([&] { writeRawlog(dir + "/valid_jpeg.rawlog", objs); });
  writeRawlog(dir + "/valid_sf.rawlog", {sf, sf});
  std::vector<std::string> expected;
  for (const auto& o : objs) expected.push_back(shape(dynamic_cast<mrpt::obs::CObservation&>(*o)));
  for (const std::string file : {"valid.rawlog", "valid_jpeg.rawlog", "valid_sf.rawlog"}) {
    RawlogSource src(dir + "/" + file);
    std::vector<std::string> got;
    while (auto obs = src.next()) got.push_back(shape(*obs));
    const size_t copies = file == "valid_sf.rawlog" ? 2 : 1;
    ASSERT_EQ(got.size(), expected.size() * copies) << file;
    for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i], expected[i % expected.size()]);
  }
}

TEST(SerializedSizeGuard, FollowsEveryModelledObservationToItsEndByte) {
  const std::string dir = scratchDir();
  auto objs = validObservations(dir);
  auto sf = mrpt::obs::CSensoryFrame::Create();
  sf->insert(makeImu(3.0));
  sf->insert(makeScan(3.0));
  objs.push_back(sf);
  for (const auto& o : objs) {
    Bytes jpeg;
    asJpeg([&] { jpeg = bytesOf(*o); });
    for (const Bytes& b : {bytesOf(*o), jpeg}) {
      EXPECT_TRUE(guardFollows(b, 1)) << o->GetRuntimeClass()->className << " byte by byte";
      EXPECT_TRUE(guardFollows(b, 4096)) << o->GetRuntimeClass()->className << " in blocks";
    }
  }
}

namespace {

/// Offset of the version byte of the first object of class `cls` in `b`.
size_t versionByteOf(const Bytes& b, const std::string& cls) {
  const auto it = std::search(b.begin(), b.end(), cls.begin(), cls.end());
  EXPECT_NE(it, b.end()) << cls;
  return static_cast<size_t>(it - b.begin()) + cls.size();
}

}  // namespace

// MRPT 2.5.8 writes only its newest versions; older ones are made by undoing what the newest
// added: a v9 range scan has no layer count (the byte before the end flag when there are
// none), a v8 CImage no pixel depth (the int32 after width, height, origin and size).
TEST(SerializedSizeGuard, FollowsOlderVersionsAndRefusesInThem) {
  Bytes scan = bytesOf(*makeScan(1.0, 64, 48));
  ASSERT_EQ(scan[scan.size() - 2], 0);
  scan.erase(scan.end() - 2);
  scan[versionByteOf(scan, "CObservation3DRangeScan")] = 9;
  auto obs = mrpt::obs::CObservationImage::Create();
  obs->image.resize(64, 48, mrpt::img::CH_GRAY);
  Bytes image = bytesOf(*obs);
  const size_t v = versionByteOf(image, "mrpt::img::CImage");
  image[v] = 8;
  image.erase(image.begin() + v + 3 + 16, image.begin() + v + 3 + 20);
  EXPECT_TRUE(guardFollows(scan, 1));
  EXPECT_TRUE(guardFollows(image, 1));
  const std::string dir = scratchDir();
  writeBytes(dir + "/old.rawlog", concat({scan, image}));
  EXPECT_EQ(readAll(dir + "/old.rawlog").delivered, 2u) << "MRPT reads them";
  put32(image, v + 3, 100000);
  put32(image, v + 7, 100000);
  EXPECT_NE(readCorrupt("old_grey.rawlog", image)
                .error.find("a CObservationImage claims a 100000 x 100000 grey image for image"),
            std::string::npos);
}
