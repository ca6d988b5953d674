// Depth-threshold segmentation against the simulator's ground truth on indoor_people_high
// (params/sim/indoor_people_high.ini at a quarter of its resolution, one frame in ten), with
// the ground-truth boxes as detections; true depth = median depth of the person's visible
// pixels.
//
// The method as method.md states it does NOT reach issue 4's targets here (mean IoU >= 0.80,
// d_t within 5 % under occlusion): the central half of a walking person's box often shows the
// wall behind, and the far 2-means cluster is then the wall, not the person (bench-segmentation
// measures it in full). What this test holds is the part that works: once d_t is right, the
// thresholds and the mask follow the person (bench, full size: IoU 0.72), and with an occluder
// in front (mild occlusion) d_t is mostly right (bench: median error 6 %).
#include <dynslam/core/Config.h>
#include <dynslam/core/Median.h>
#include <dynslam/segmentation/DepthThresholdSegmenter.h>
#include <dynslam/segmentation/MaskQuality.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace dynslam;

namespace {

sim::ScenarioOptions quarterResolution(const std::string& ini) {
  sim::ScenarioOptions o;
  o.load(core::IniConfig::fromFile(
      ini, {"Scenario.width=320", "Scenario.height=240", "Scenario.fx=262.5", "Scenario.fy=262.5",
            "Scenario.cx=159.5", "Scenario.cy=119.5"}));
  return o;
}

}  // namespace

TEST(SegmentationSim, OnceTheDepthIsRightTheMaskFollowsThePerson) {
  const std::string ini = dynslam::testing::sourceDir() + "/params/sim/indoor_people_high.ini";
  const sim::Simulator simulator(quarterResolution(ini));
  const segmentation::DepthThresholdSegmenter segmenter(segmentation::methodParams());

  std::vector<double> iouRightDepth, mildErr;
  int scored = 0;
  sim::SimFrame f;
  for (size_t i = 0; i < simulator.frameCount(); i += 10) {
    simulator.renderFrame(i, f);
    std::vector<core::Detection> detections;
    std::vector<const sim::ObjectTruth*> truths;
    for (const auto& o : f.objects) {
      if (o.visible_pixels == 0) continue;  // a detector cannot see it
      core::Detection d;
      d.box = o.box;
      d.category = o.category;
      d.truth_id = o.id;
      detections.push_back(d);
      truths.push_back(&o);
    }
    const auto masks = segmenter.segment(f.image.depth, detections);
    ASSERT_EQ(masks.size(), detections.size());
    for (size_t k = 0; k < masks.size(); ++k) {
      const auto& o = *truths[k];
      const double truth = segmentation::visibleMedianDepth(f.image.depth, f.image.label, o.id);
      if (o.visible_fraction < 0.5 || truth <= 0 || !masks[k].valid) continue;
      ++scored;
      const double err = std::abs(masks[k].d_t - truth) / truth;
      if (err <= 0.05)
        iouRightDepth.push_back(segmentation::maskIoU(masks[k], f.image.label == o.id));
      if (o.visible_fraction < 0.9) mildErr.push_back(err);
    }
  }
  ASSERT_GT(scored, 100) << "people in view";
  ASSERT_GT(iouRightDepth.size(), 30u);
  ASSERT_GT(mildErr.size(), 30u);
  double iouSum = 0;
  for (double x : iouRightDepth) iouSum += x;
  const double meanIoU = iouSum / iouRightDepth.size();
  std::printf(
      "[ INFO ] %d people at least half visible; d_t within 5 %% for %zu: their mean "
      "IoU %.3f; %zu mildly occluded: median d_t error %.1f %%\n",
      scored, iouRightDepth.size(), meanIoU, mildErr.size(),
      100 * dynslam::core::upperMedian(mildErr));
  EXPECT_GE(meanIoU, 0.65);
  EXPECT_LE(dynslam::core::upperMedian(mildErr), 0.10);
}
