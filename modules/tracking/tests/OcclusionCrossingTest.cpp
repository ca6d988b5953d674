// Paper Fig. 10, staged in the simulator: a person crosses the room behind another who walks
// towards and away from the camera, is hidden by them (less than 5 % visible) for about 0.8 s
// and gets no detection for about 1.2 s (the partial occlusion before and after hides them from
// the detector too), and must come out with the ID it went in with.
//
// Detections are the simulator's ground-truth boxes of people at least 20 % visible (what
// GroundTruthDetector reports by default) with 3 px of Gaussian jitter on each edge; the object
// depth is the true one (median depth of the person's visible pixels), so the test is about the
// tracker, not the segmentation. Four jitter seeds on the same rendering.
//
// The tracker runs with rho_min = 0.5 and a second round for coasting tracks at 0.3 (and again
// with the paper's 0.7 plus the colour re-identification, reid_max_distance 0.7 and reid_memory
// 10): with the paper's 0.7 alone the reappearing person is taken up again in only a few of the
// seeds (the prediction after 1.2 s of coasting is off by a fifth of the box: the gait swings the
// box width).
#include <dynslam/core/Config.h>
#include <dynslam/sim/Simulator.h>
#include <dynslam/tracking/TrackingStage.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

using namespace dynslam;

namespace {

/// A slowly turning camera (3 deg/s, no hand bob) at (1.8, 0) looking at the room's centre
/// (-x). Person 1 walks towards and away from it on y = 0.1, 1.2-1.5 m away; person 2 crosses
/// the room at x = -1.6, 3.4 m away, behind person 1.
sim::ScenarioOptions crossingScenario() {
  sim::ScenarioOptions o;
  o.world.scene = "room";
  o.world.seed = 11;
  o.world.duration = 4.5;
  o.world.fps = 30;
  o.camera.orbit_period = 120;
  o.camera.bob_amplitude = 0;
  o.people.walkers = 0;
  o.people.standing = 0;
  o.people.speed = 1.0;
  o.people.waypoints = "0.6,0.1 0.3,0.1 | -1.6,-2.2 -1.6,2.2";
  return o;
}

constexpr int kHiddenPerson = 2;
constexpr double kMinVisible = 0.2;

/// Median depth of the pixels labelled `id`; 0 when none has depth.
double visibleDepth(const sim::SimFrame& f, uint16_t id) {
  std::vector<float> depths;
  for (int v = 0; v < f.image.label.rows; ++v)
    for (int u = 0; u < f.image.label.cols; ++u)
      if (f.image.label.at<uint16_t>(v, u) == id && f.image.depth.at<float>(v, u) > 0)
        depths.push_back(f.image.depth.at<float>(v, u));
  if (depths.empty()) return 0;
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  return depths[depths.size() / 2];
}

struct TruthObject {
  int id;
  cv::Rect2f box;
  double visible_fraction, depth;
};

/// The rendered scenario: per frame its time, images and each object's truth.
struct Rendering {
  std::vector<std::vector<TruthObject>> truth;
  std::vector<double> times;
  std::vector<cv::Mat> images, depths;  // for the colour re-identification
};

Rendering render(const sim::Simulator& simulator) {
  Rendering r;
  r.truth.resize(simulator.frameCount());
  r.times.resize(simulator.frameCount());
  r.images.resize(simulator.frameCount());
  r.depths.resize(simulator.frameCount());
  sim::SimFrame sf;
  for (size_t i = 0; i < simulator.frameCount(); ++i) {
    simulator.renderFrame(i, sf);
    r.times[i] = sf.t;
    r.images[i] = sf.image.rgb.clone();
    r.depths[i] = sf.image.depth.clone();
    for (const auto& o : sf.objects)
      r.truth[i].push_back({o.id, cv::Rect2f(o.box), o.visible_pixels ? o.visible_fraction : 0.0,
                            visibleDepth(sf, o.id)});
  }
  return r;
}

/// Frame i as the Tracking stage gets it: the people at least kMinVisible visible as detections
/// with 3 px of jitter on each edge, their true depth as the mask's d_t; `truthOf` the truth id
/// of each detection.
core::Frame detectorFrame(const Rendering& r, size_t i, std::mt19937& rng,
                          std::normal_distribution<float>& jitter, std::vector<int>& truthOf) {
  core::Frame frame;
  frame.index = i;
  frame.t = r.times[i];
  frame.detections_fresh = true;
  truthOf.clear();
  for (const auto& o : r.truth[i]) {
    if (o.visible_fraction < kMinVisible) continue;
    core::Detection d;
    const float x0 = o.box.x + jitter(rng), y0 = o.box.y + jitter(rng);
    const float x1 = o.box.br().x + jitter(rng), y1 = o.box.br().y + jitter(rng);
    d.box = cv::Rect2f(x0, y0, x1 - x0, y1 - y0) & cv::Rect2f(0, 0, 640, 480);
    d.category = "person";
    core::ObjectMask m;
    m.detection = int(frame.detections.size());
    m.valid = o.depth > 0;
    m.d_t = o.depth;
    frame.detections.push_back(d);
    frame.object_masks.push_back(m);
    truthOf.push_back(o.id);
  }
  frame.rgb = r.images[i];
  frame.depth = r.depths[i];
  return frame;
}

/// The ids person 2's confirmed tracks had before and after the frames [undetectedFirst,
/// undetectedLast] without detection (-1: none), and the ids person 1's had.
struct IdsSeen {
  int before = -1, after = -1;
  std::set<int> ofPerson1;
};

IdsSeen runStage(const Rendering& r, const std::string& settings, uint32_t seed,
                 size_t undetectedFirst, size_t undetectedLast) {
  tracking::TrackingStage stage;
  stage.configure(core::IniConfig::fromText("[Tracking]\n" + settings), "Tracking");
  std::mt19937 rng(seed);
  std::normal_distribution<float> jitter(0.f, 3.f);  // one per run: it keeps a drawn value
  IdsSeen ids;
  std::vector<int> truthOf;
  for (size_t i = 0; i < r.truth.size(); ++i) {
    core::Frame frame = detectorFrame(r, i, rng, jitter, truthOf);
    stage.process(frame);
    for (const auto& t : frame.tracks) {
      if (t.detection < 0 || t.state != core::TrackState::Confirmed) continue;
      if (truthOf[t.detection] == 1) ids.ofPerson1.insert(t.id);
      if (truthOf[t.detection] != kHiddenPerson) continue;
      if (i < undetectedFirst) ids.before = t.id;
      if (i > undetectedLast && ids.after < 0) ids.after = t.id;
    }
  }
  return ids;
}

}  // namespace

TEST(TrackingOcclusion, PersonHiddenBehindAnotherKeepsItsId) {
  const Rendering r = render(sim::Simulator(crossingScenario()));

  // The staging: one stretch in which person 2 is under 5 % visible for about 0.8 s, inside a
  // longer one without detection.
  size_t hidden = 0, undetectedFirst = 0, undetectedLast = 0;
  for (size_t i = 0; i < r.truth.size(); ++i)
    for (const auto& o : r.truth[i])
      if (o.id == kHiddenPerson) {
        hidden += o.visible_fraction < 0.05;
        if (o.visible_fraction < kMinVisible) {
          if (!undetectedFirst) undetectedFirst = i;
          undetectedLast = i;
        }
      }
  ASSERT_GT(undetectedFirst, 10u) << "person 2 is seen before it is hidden";
  const size_t undetected = undetectedLast - undetectedFirst + 1;
  EXPECT_NEAR(hidden / 30.0, 0.8, 0.15) << "seconds under 5 % visible";
  EXPECT_NEAR(undetected / 30.0, 1.2, 0.2) << "seconds without detection";
  ASSERT_LT(undetectedLast + 10, r.truth.size()) << "and seen again after";

  // The settings that bridge the hide: a lower threshold for coasting tracks, or the paper's 0.7
  // with the colour re-identification (reid_max_distance 0.7, reid_memory 10: the defaults),
  // each without the defaults' other departures; or the defaults (the shipped tracker: rho_min
  // 0.5, the re-identification, innovation_gate, depth_gate, no second round).
  const std::string noGates = "alternative_depth = false\ndepth_gate = 0\ninnovation_gate = 0\n";
  for (const std::string& settings :
       {noGates + "min_hits = 3\nreid_max_distance = 0\nreid_memory = 0\nrho_min = 0.5\n"
                  "rho_min_coasting = 0.3\n",
        noGates + "min_hits = 3\nrho_min = 0.7\n", std::string()})
    for (uint32_t seed : {1u, 2u, 3u, 4u}) {
      SCOPED_TRACE(settings);
      const IdsSeen ids = runStage(r, settings, seed, undetectedFirst, undetectedLast);
      ASSERT_GE(ids.before, 0) << "seed " << seed << ": person 2 was tracked before";
      EXPECT_EQ(ids.after, ids.before) << "seed " << seed << ": person 2, " << undetected
                                       << " frames without detection, came back as another track";
      EXPECT_EQ(ids.ofPerson1.size(), 1u) << "seed " << seed << ": the occluder kept its ID";
    }
}
