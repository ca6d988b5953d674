// System as an embedding program uses it: a simulated rawlog's observations fed one by one,
// the outputs read from subscriptions, sinks and getters.
#include <dynslam/core/Frame.h>
#include <dynslam/io/RawlogSource.h>
#include <dynslam/io/SensorSync.h>
#include <dynslam/system/System.h>
#include <dynslam/testing/TestEnv.h>

#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace dynslam::system {
namespace {

using testing::binDir;
using testing::runCommand;
using testing::sourceDir;
using Observations = std::vector<std::shared_ptr<mrpt::obs::CObservation>>;

/// Two simulated seconds of indoor_people_high, rendered once for every test here.
class SystemTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // A folder per process: ctest runs each test of the suite in a process of its own, at once.
    dir_ = new std::string(testing::scratchDir("SystemTest-" + std::to_string(getpid())));
    const auto render = runCommand(binDir() + "/dynslam-sim --config " + sourceDir() +
                                   "/params/sim/indoor_people_high.ini --out " + *dir_ +
                                   " --set Scenario.duration=2 --quiet");
    ASSERT_EQ(render.exit_code, 0) << render.output;
    io::RawlogSource source(*dir_ + "/sim.rawlog");
    observations_ = new Observations;
    while (auto o = source.next()) observations_->push_back(o);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete observations_;
    delete dir_;
  }

  /// The system of the demo with the ground-truth detector; solves end on their iteration
  /// count, so two runs give the same poses.
  static std::vector<std::string> overrides() {
    return {"Detection.objects=" + *dir_ + "/objects.txt", "Estimator.dynamic_handling=full",
            "Estimator.max_solver_time=100"};
  }
  static std::string ini() { return sourceDir() + "/params/sim_vio.ini"; }

  static std::string* dir_;
  static Observations* observations_;
};
std::string* SystemTest::dir_ = nullptr;
Observations* SystemTest::observations_ = nullptr;

/// Counts what a sink sees.
struct CountingSink : FrameSink {
  std::atomic<int> frames{0}, ends{0};
  std::vector<double> stamps;
  void onFrame(const core::Frame& frame, const FrameContext& context) override {
    ++frames;
    stamps.push_back(frame.t);
    EXPECT_GE(context.process_ms, 0.0);
  }
  void onEnd() override { ++ends; }
};

std::vector<mrpt::math::TPose3D> posesOf(const std::string& ini,
                                         const std::vector<std::string>& overrides,
                                         const Observations& observations, bool synchronous) {
  SystemSettings settings;
  settings.synchronous = synchronous;
  System system(ini, overrides, settings);
  std::vector<mrpt::math::TPose3D> poses;
  system.subscribeToLocalization([&](const LocalizationUpdate& u) { poses.push_back(u.pose); });
  for (const auto& o : observations) system.onNewObservation(o);
  system.flush();
  return poses;
}

TEST_F(SystemTest, ThreadedAndSynchronousPlaybackGiveTheSamePoses) {
  const auto threaded = posesOf(ini(), overrides(), *observations_, false);
  const auto synchronous = posesOf(ini(), overrides(), *observations_, true);
  ASSERT_GT(threaded.size(), 50u) << "two seconds at 30 Hz";
  ASSERT_EQ(threaded.size(), synchronous.size());
  for (size_t i = 0; i < threaded.size(); ++i) EXPECT_EQ(threaded[i], synchronous[i]) << i;
}

TEST_F(SystemTest, SinksSubscriptionsAndGettersSeeEveryFrame) {
  System system(ini(), overrides());
  EXPECT_EQ(system.status(), TrackingStatus::Initializing);
  EXPECT_FALSE(system.latestPose());
  auto sink = std::make_shared<CountingSink>();
  system.addSink(sink);
  std::vector<LocalizationUpdate> poses;
  system.subscribeToLocalization([&](const LocalizationUpdate& u) { poses.push_back(u); });
  size_t mapUpdates = 0, mapPoints = 0;
  system.subscribeToMapUpdates([&](const MapUpdate& u) {
    ++mapUpdates;
    const auto* points = dynamic_cast<const mrpt::maps::CColouredPointsMap*>(u.map.get());
    ASSERT_NE(points, nullptr);
    mapPoints = points->size();
    EXPECT_EQ(u.reference_frame, "map");
  });
  for (const auto& o : *observations_) system.onNewObservation(o);
  system.flush();

  const io::SyncCounts counts = system.counts();
  EXPECT_EQ(size_t(sink->frames), counts.frames);
  EXPECT_EQ(sink->ends, 1);
  EXPECT_EQ(system.framesProcessed(), counts.frames);
  EXPECT_EQ(poses.size(), counts.frames) << "the estimator poses every frame of this sequence";
  EXPECT_EQ(system.status(), TrackingStatus::Tracking);
  ASSERT_TRUE(system.latestPose());
  EXPECT_EQ(system.latestPose()->pose, poses.back().pose);
  EXPECT_EQ(system.latestPose()->timestamp, mrpt::Clock::fromDouble(sink->stamps.back()));
  ASSERT_TRUE(system.latestVelocity());
  EXPECT_LT(system.latestVelocity()->norm(), 3.0) << "a hand-held camera's speed";
  EXPECT_GE(mapUpdates, 2u) << "one frame in 10 adds to the map";
  EXPECT_GT(mapPoints, 1000u);
  // params/sim_vio.ini's ObjectStates stage: filtered states with their covariance.
  EXPECT_FALSE(system.movingObjects().empty()) << "people walk through the 2 s";
  for (const auto& object : system.movingObjects()) {
    EXPECT_EQ(object.category, "person") << object.id;
    EXPECT_LE(object.last_seen, system.latestPose()->timestamp);
    EXPECT_GT(object.extent.y, 0.3) << "a person's height in view";
    ASSERT_TRUE(object.cov) << object.id;
    EXPECT_GT((*object.cov)(0, 0), 0.0);
    EXPECT_LT(std::hypot(object.velocity.x, object.velocity.y), 3.0) << "a walker's speed";
  }
}

TEST_F(SystemTest, ObservationTypesItDoesNotUseAreCountedAndIgnored) {
  System system(ini(), overrides());
  auto odometry = mrpt::obs::CObservationOdometry::Create();
  odometry->timestamp = mrpt::Clock::fromDouble(1.0);
  system.onNewObservation(odometry);
  system.flush();
  EXPECT_EQ(system.counts().other, 1u);
  EXPECT_EQ(system.counts().by_type.count("mrpt::obs::CObservationOdometry"), 1u);
  EXPECT_EQ(system.framesProcessed(), 0u);
  EXPECT_EQ(system.status(), TrackingStatus::Initializing);
}

TEST_F(SystemTest, AStreamOutOfOrderIsAnErrorAndTheSinksStillEnd) {
  for (const bool synchronous : {true, false}) {
    SCOPED_TRACE(synchronous ? "synchronous" : "threaded");
    SystemSettings settings;
    settings.synchronous = synchronous;
    System system(ini(), overrides(), settings);
    auto sink = std::make_shared<CountingSink>();
    system.addSink(sink);
    auto late = mrpt::obs::CObservationIMU::Create();
    late->sensorLabel = "IMU";
    late->timestamp = mrpt::Clock::fromDouble(1.0);  // long before the sequence's stamps
    std::string error;
    try {
      for (size_t i = 0; i < 200; ++i) system.onNewObservation((*observations_)[i]);
      system.onNewObservation(late);
      system.flush();
    } catch (const io::SyncError& e) {
      error = e.what();
    }
    EXPECT_NE(error.find("out-of-order timestamp"), std::string::npos) << error;
    EXPECT_NE(error.find("CObservationIMU"), std::string::npos) << error;
    system.stop();
    EXPECT_EQ(sink->ends, 1) << "the sinks end after an error: their files are complete";
    EXPECT_GT(sink->frames, 0) << "the frames before the error were processed";
    EXPECT_THROW(system.onNewObservation((*observations_)[0]), std::logic_error);
  }
}

TEST_F(SystemTest, SinksAndSubscriptionsComeBeforeTheFirstObservation) {
  System system(ini(), overrides());
  system.onNewObservation((*observations_)[0]);
  EXPECT_THROW(system.addSink(std::make_shared<CountingSink>()), std::logic_error);
  EXPECT_THROW(system.subscribeToLocalization([](const LocalizationUpdate&) {}), std::logic_error);
  system.stop();
}

TEST_F(SystemTest, StopEndsSoonWithWhatWasDone) {
  System system(ini(), overrides());
  auto sink = std::make_shared<CountingSink>();
  system.addSink(sink);
  for (const auto& o : *observations_) system.onNewObservation(o);
  system.stop();
  EXPECT_EQ(sink->ends, 1);
  EXPECT_LE(size_t(sink->frames), system.counts().rgbd);
  EXPECT_EQ(system.framesProcessed(), size_t(sink->frames));
}

TEST_F(SystemTest, ABadConfigurationNamesTheKey) {
  try {
    auto bad = overrides();
    bad.push_back("Estimator.no_such_key=1");
    System system(ini(), bad);
    FAIL() << "an unknown key must be refused";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_key"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dynslam::system
