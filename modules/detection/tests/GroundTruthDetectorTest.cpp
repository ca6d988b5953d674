// The ground-truth detector: boxes and ids from objects.txt matched by stamp, and the degradations
// that make it behave like a real detector (visibility cut, misses, jitter, false positives),
// repeatable by seed.
#include <dynslam/detection/GroundTruthDetector.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/core/Clock.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace det = dynslam::detection;
namespace dt = dynslam::testing;
using dynslam::core::Frame;

namespace {

constexpr double kT0 = 1700000000.0;
constexpr double kDt = 1.0 / 30.0;
constexpr int kFrames = 400;

/// objects.txt of `kFrames` frames, as dynslam-sim writes it: person 3 (fully visible), person 4
/// (10 % visible, behind another), car 7 (visible; a car), person 9 (in view but hidden by a wall).
std::string writeObjects() {
  std::ostringstream out;
  out.precision(17);
  out << "# frame t id class moving tx ty tz qx qy qz qw box_x box_y box_w box_h visible_pixels "
         "visible_fraction\n";
  for (int f = 0; f < kFrames; ++f) {
    const double t = kT0 + f * kDt;
    out << f << ' ' << t << " 3 person 1 1 2 0.9 0 0 0 1 100 50 40 120 4000 1\n";
    out << f << ' ' << t << " 4 person 1 1 3 0.9 0 0 0 1 110 60 40 120 400 0.1\n";
    out << f << ' ' << t << " 7 car 0 4 5 0 0 0 0 1 300 200 160 90 12000 0.95\n";
    out << f << ' ' << t << " 9 person 1 9 9 0.9 0 0 0 1 500 10 30 90 0 0\n";
  }
  return dt::writeTextFile(dt::scratchDir() + "/objects.txt", out.str());
}

/// A frame as the pipeline sees it: the stamp went through the rawlog's 100 ns clock.
Frame frameAt(int f) {
  Frame frame;
  frame.index = static_cast<std::size_t>(f);
  frame.t = mrpt::Clock::toDouble(mrpt::Clock::fromDouble(kT0 + f * kDt));
  frame.intrinsics.width = 640;
  frame.intrinsics.height = 480;
  return frame;
}

}  // namespace

TEST(GroundTruthDetector, ReportsVisibleObjectsWithTheirIdsAndExactBoxesWhenNoiseIsOff) {
  det::GroundTruthDetectorSettings settings;
  settings.objects = writeObjects();
  det::GroundTruthDetector detector(settings, det::ClassMap());
  const auto found = detector.detect(frameAt(17));
  ASSERT_EQ(found.size(), 2u);  // 4: 10 % visible < 0.2; 9: no visible pixel
  EXPECT_EQ(found[0].truth_id, 3);
  EXPECT_EQ(found[0].category, "person");
  EXPECT_EQ(found[0].model, dynslam::core::MotionModel::NonRigid);
  EXPECT_EQ(found[0].box, cv::Rect2f(100, 50, 40, 120));
  EXPECT_FLOAT_EQ(found[0].score, 1.f);
  EXPECT_EQ(found[1].truth_id, 7);
  EXPECT_EQ(found[1].model, dynslam::core::MotionModel::Rigid);

  settings.min_visible_fraction = 0.05;
  det::GroundTruthDetector sees_more(settings, det::ClassMap::parse("person:person:non_rigid"));
  const auto more = sees_more.detect(frameAt(17));
  ASSERT_EQ(more.size(), 2u);  // 4 now reported; the car dropped by the class map; 9 never
  EXPECT_EQ(more[0].truth_id, 3);
  EXPECT_EQ(more[1].truth_id, 4);
  // A frame between two listed stamps matches none.
  Frame between = frameAt(17);
  between.t += 0.5 * kDt;
  EXPECT_TRUE(sees_more.detect(between).empty());
}

TEST(GroundTruthDetector, MissRateJitterAndFalsePositivesHaveTheirSettingsStatistics) {
  det::GroundTruthDetectorSettings settings;
  settings.objects = writeObjects();
  settings.miss_rate = 0.3;
  settings.jitter_px = 3.0;
  settings.false_positive_rate = 0.5;
  det::GroundTruthDetector detector(settings, det::ClassMap());
  int reported = 0, false_positives = 0;
  double sum_dx = 0, sum_dx2 = 0;
  int edges = 0;
  for (int f = 0; f < kFrames; ++f) {
    for (const auto& d : detector.detect(frameAt(f))) {
      if (d.truth_id < 0) {
        ++false_positives;
        EXPECT_GE(d.box.x, 0.f);
        EXPECT_LE(d.box.x + d.box.width, 640.f);
        EXPECT_LE(d.box.y + d.box.height, 480.f);
        continue;
      }
      ++reported;
      if (d.truth_id == 3) {
        for (const double e : {d.box.x - 100.0, d.box.x + d.box.width - 140.0}) {
          sum_dx += e, sum_dx2 += e * e, ++edges;
        }
      }
    }
  }
  // 2 reportable objects per frame, 30 % missed: 560 expected (binomial sd 13).
  EXPECT_NEAR(reported, 0.7 * 2 * kFrames, 60);
  // Poisson(0.5) per frame: 200 expected (sd 14).
  EXPECT_NEAR(false_positives, 0.5 * kFrames, 60);
  const double mean = sum_dx / edges, sd = std::sqrt(sum_dx2 / edges - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.5);
  EXPECT_NEAR(sd, 3.0, 0.4);
}

TEST(GroundTruthDetector, SameSeedSameBoxesWhateverFramesCameBefore) {
  det::GroundTruthDetectorSettings settings;
  settings.objects = writeObjects();
  settings.miss_rate = 0.2;
  settings.jitter_px = 2.0;
  settings.false_positive_rate = 1.0;
  det::GroundTruthDetector a(settings, det::ClassMap()), b(settings, det::ClassMap());
  for (int f = 0; f < 50; ++f) a.detect(frameAt(f));  // b skips these (real-time mode does)
  const auto boxesOf = [](const std::vector<dynslam::core::Detection>& ds) {
    std::vector<cv::Rect2f> boxes;
    for (const auto& d : ds) boxes.push_back(d.box);
    return boxes;
  };
  EXPECT_EQ(boxesOf(a.detect(frameAt(50))), boxesOf(b.detect(frameAt(50))));
  settings.seed = 2;
  det::GroundTruthDetector c(settings, det::ClassMap());
  int differing = 0;
  for (int f = 60; f < 70; ++f)
    differing += boxesOf(b.detect(frameAt(f))) != boxesOf(c.detect(frameAt(f)));
  EXPECT_GT(differing, 5);
}

TEST(GroundTruthDetector, FrameOfAnotherSequenceAndBadFilesAreErrors) {
  det::GroundTruthDetectorSettings settings;
  settings.objects = writeObjects();
  det::GroundTruthDetector detector(settings, det::ClassMap());
  Frame far = frameAt(0);
  far.t = kT0 - 100;
  EXPECT_THROW(detector.detect(far), det::DetectorError);

  settings.objects = dt::scratchDir() + "/absent.txt";
  EXPECT_THROW(det::GroundTruthDetector(settings, det::ClassMap()),
               dynslam::core::ObjectGroundTruthError);
  settings.objects = dt::writeTextFile(dt::scratchDir() + "/objects.txt",
                                       "0 1.0 3 pedestrian 1 0 0 0 0 0 0 1 0 0 1 1 1 1\n");
  try {
    det::GroundTruthDetector unknown_class(settings, det::ClassMap());
    FAIL() << "no error for an unknown class";
  } catch (const det::DetectorError& e) {
    EXPECT_NE(std::string(e.what()).find("'pedestrian'"), std::string::npos) << e.what();
  }
}
