// The detector thread: the pipeline never waits for it, the detector takes the newest frame, each
// result is delivered at most once and in frame order, and a detector's exception reaches the
// pipeline.
#include <dynslam/detection/RealtimeDetector.h>

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace det = dynslam::detection;
using dynslam::core::Frame;

namespace {

/// A detector that holds each detection until the test opens its gate, and reports the frame
/// index it saw as the box's x.
class GatedDetector : public det::Detector {
 public:
  struct Gate {
    std::mutex mutex;
    std::condition_variable changed;
    bool open = false;
    int started = 0;
  };
  explicit GatedDetector(Gate& gate) : gate_(gate) {}

  std::vector<dynslam::core::Detection> detect(const Frame& frame) override {
    std::unique_lock lock(gate_.mutex);
    ++gate_.started;
    gate_.changed.notify_all();
    // Bounded wait: a broken stage fails the test instead of hanging it.
    gate_.changed.wait_for(lock, std::chrono::seconds(10), [&] { return gate_.open; });
    if (frame.rgb.empty()) throw det::DetectorError("no image");
    dynslam::core::Detection d;
    d.box = cv::Rect2f(static_cast<float>(frame.index), 0, 1, 1);
    return {d};
  }

 private:
  Gate& gate_;
};

Frame frameNumber(std::size_t i) {
  Frame f;
  f.index = i;
  f.t = 0.1 * static_cast<double>(i);
  f.rgb = cv::Mat(4, 4, CV_8UC3, cv::Scalar::all(static_cast<double>(i)));
  return f;
}

}  // namespace

TEST(RealtimeDetector, PipelineGoesOnWhileTheDetectorIsBusyAndItTakesTheNewestFrameNext) {
  GatedDetector::Gate gate;
  det::RealtimeDetector realtime(std::make_unique<GatedDetector>(gate));
  ASSERT_TRUE(realtime.submit(frameNumber(0)));  // idle: taken at once
  {
    std::unique_lock lock(gate.mutex);
    gate.changed.wait_for(lock, std::chrono::seconds(10), [&] { return gate.started == 1; });
  }
  // While detection of frame 0 is held, 20 more frames pass: none waits for the detector.
  for (std::size_t i = 1; i <= 20; ++i) {
    EXPECT_FALSE(realtime.poll());
    EXPECT_FALSE(realtime.submit(frameNumber(i)));  // busy: left in the mailbox
  }
  {
    std::lock_guard lock(gate.mutex);
    EXPECT_FALSE(gate.open);  // all of the above happened with the detector still held
    EXPECT_EQ(gate.started, 1);
    gate.open = true;
  }
  gate.changed.notify_all();
  realtime.waitIdle();
  // Frame 0, then at once frame 20 (1..19 were replaced in the mailbox); the newest result
  // is the one delivered, frame 0's is dropped as superseded.
  EXPECT_EQ(realtime.completed(), 2u);
  const auto result = realtime.poll();
  ASSERT_TRUE(result);
  EXPECT_EQ(result->frame_index, 20u);
  ASSERT_EQ(result->detections.size(), 1u);
  EXPECT_EQ(result->detections[0].box.x, 20.f);
  EXPECT_EQ(realtime.dropped(), 1u);
  EXPECT_FALSE(realtime.poll());  // delivered once
}

TEST(RealtimeDetector, DeliversEachResultOnceAndInFrameOrder) {
  GatedDetector::Gate gate;
  gate.open = true;
  det::RealtimeDetector realtime(std::make_unique<GatedDetector>(gate));
  std::vector<std::size_t> delivered;
  for (std::size_t i = 0; i < 300; ++i) {
    if (auto r = realtime.poll()) {
      EXPECT_EQ(r->detections.at(0).box.x, static_cast<float>(r->frame_index));
      EXPECT_LT(r->frame_index, i);  // from a frame handed over earlier
      delivered.push_back(r->frame_index);
    }
    realtime.submit(frameNumber(i));
  }
  realtime.waitIdle();
  if (auto r = realtime.poll()) delivered.push_back(r->frame_index);
  ASSERT_FALSE(delivered.empty());
  for (std::size_t k = 1; k < delivered.size(); ++k) EXPECT_LT(delivered[k - 1], delivered[k]);
  EXPECT_EQ(delivered.back(), 299u);  // the last frame is detected once the pipeline waits
  EXPECT_EQ(realtime.completed(), delivered.size() + realtime.dropped());
}

TEST(RealtimeDetector, ADetectorErrorReachesThePipeline) {
  GatedDetector::Gate gate;
  gate.open = true;
  det::RealtimeDetector realtime(std::make_unique<GatedDetector>(gate));
  Frame no_image = frameNumber(3);
  no_image.rgb.release();
  ASSERT_TRUE(realtime.submit(no_image));
  realtime.waitIdle();
  EXPECT_THROW(realtime.poll(), det::DetectorError);
  EXPECT_FALSE(realtime.poll());  // rethrown once; the detector goes on
  EXPECT_TRUE(realtime.submit(frameNumber(4)));
  realtime.waitIdle();
  EXPECT_EQ(realtime.poll()->frame_index, 4u);
}
