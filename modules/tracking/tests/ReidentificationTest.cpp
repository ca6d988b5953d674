// The appearance cue (Appearance.h) and what the tracker does with it: reid_max_distance and
// reid_memory (KalmanBoxTracker.h).
#include "TrackerTestSupport.h"

#include <dynslam/tracking/Appearance.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;
using namespace dynslam::tracking;
using namespace dynslam::tracking::testing;

namespace {

/// A descriptor with all its weight in one colour bin.
cv::Mat colour(int bin) {
  cv::Mat h = cv::Mat::zeros(1, kAppearanceBins, CV_32F);
  h.at<float>(bin) = 1.f;
  return h;
}

BoxObservation dressed(BoxObservation o, int colourBin) {
  o.appearance = colour(colourBin);
  return o;
}

}  // namespace

TEST(TrackingAppearance, BodyHistogramTellsShirtsAndTrousersApart) {
  cv::Mat redBlue(200, 100, CV_8UC3, cv::Scalar(0, 0, 200));        // red shirt
  redBlue(cv::Rect(0, 110, 100, 90)).setTo(cv::Scalar(200, 0, 0));  // blue trousers
  const cv::Mat a = bodyHistogram(redBlue, cv::Rect2f(0, 0, 100, 200));
  ASSERT_FALSE(a.empty());
  EXPECT_NEAR(cv::sum(a)[0], 1.0, 1e-5);
  EXPECT_NEAR(appearanceDistance(a, a), 0.0, 1e-6);
  cv::Mat redGreen = redBlue.clone();  // same shirt, other trousers
  redGreen(cv::Rect(0, 110, 100, 90)).setTo(cv::Scalar(0, 200, 0));
  const double trousers =
      appearanceDistance(a, bodyHistogram(redGreen, cv::Rect2f(0, 0, 100, 200)));
  EXPECT_GT(trousers, 0.5) << "the legs count as half";
  EXPECT_LT(trousers, 0.9);
  cv::Mat green(200, 100, CV_8UC3, cv::Scalar(0, 200, 0));
  EXPECT_GT(appearanceDistance(a, bodyHistogram(green, cv::Rect2f(0, 0, 100, 200))), 0.99);
  EXPECT_EQ(appearanceDistance(a, cv::Mat()), 1.0);
  EXPECT_TRUE(bodyHistogram(redBlue, cv::Rect2f(0, 0, 4, 4)).empty()) << "too few pixels";
}

// A red person 3 m away, the left half of its box covered by a green person 1.5 m away: with the
// depth band the descriptor is the red person's alone.
TEST(TrackingAppearance, DepthBandLeavesTheOccluderOut) {
  cv::Mat image(200, 100, CV_8UC3, cv::Scalar(0, 0, 200));
  cv::Mat depth(200, 100, CV_32FC1, cv::Scalar(3.0f));
  image(cv::Rect(0, 0, 50, 200)).setTo(cv::Scalar(0, 200, 0));
  depth(cv::Rect(0, 0, 50, 200)).setTo(cv::Scalar(1.5f));
  const cv::Mat red =
      bodyHistogram(cv::Mat(200, 100, CV_8UC3, cv::Scalar(0, 0, 200)), cv::Rect2f(0, 0, 100, 200));
  const cv::Rect2f box(0, 0, 100, 200);
  EXPECT_LT(appearanceDistance(red, bodyHistogram(image, box, depth, 3.0)), 1e-6);
  EXPECT_GT(appearanceDistance(red, bodyHistogram(image, box)), 0.5) << "without the band";
  EXPECT_TRUE(bodyHistogram(image, box, depth, 6.0).empty()) << "nothing at that depth";
}

// A red person 3 m away, hidden for 20 frames, steps out from behind a green one 1.5 m away and
// is given the green one's depth (the segmentation took the occluder's surface, which the
// occluder's own detection has): its descriptor shows green and its depth is off by a factor 2.
// With reid_at_track_depth the coasting track looks at the box at its own depth, finds red there
// and takes the detection; without, a new track starts. A green person at 1.5 m with nothing red
// behind it is not taken either way.
TEST(TrackingKalmanBoxTracker, ReidentificationAtTheTracksDepthFindsAPersonGivenTheOccludersDepth) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(0, 0, 200));
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(3.0f));
  image(cv::Rect(0, 0, 215, 480)).setTo(cv::Scalar(0, 200, 0));  // the occluder's side
  depth(cv::Rect(0, 0, 215, 480)).setTo(cv::Scalar(1.5f));
  const cv::Mat green(480, 640, CV_8UC3, cv::Scalar(0, 200, 0));
  const cv::Mat near(480, 640, CV_32FC1, cv::Scalar(1.5f));
  auto run = [&](double atTrackDepth, const cv::Mat& img, const cv::Mat& z) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = 0.4;
    params.reid_at_track_depth = atTrackDepth;
    KalmanBoxTracker tracker(params);
    const cv::Mat red =
        bodyHistogram(cv::Mat(480, 640, CV_8UC3, cv::Scalar(0, 0, 200)), cv::Rect2f(0, 0, 60, 180));
    int k = 0;
    for (; k < 10; ++k) {
      BoxObservation o = person(100 + 10.f * k, 100, 60, 180, 3.0);
      o.appearance = red;
      step(tracker, k, {o});
    }
    for (; k < 30; ++k) step(tracker, k, {});
    // The occluder (its own detection) and the person stepping out beside it.
    BoxObservation occluder = person(100, 60, 115, 300, 1.5);
    BoxObservation o = person(180, 100, 60, 180, 1.5);
    for (BoxObservation* b : {&occluder, &o}) {
      const cv::Rect2f box = b->box;
      b->appearance = bodyHistogram(img, box, z, 1.5);
      b->appearance_at = [&, box](double d) { return bodyHistogram(img, box, z, d); };
    }
    for (const auto& t : step(tracker, k, {occluder, o}))
      if (t.detection == 1) return t.id;
    return -1;
  };
  EXPECT_NE(run(0.0, image, depth), 1) << "without: a new track";
  EXPECT_EQ(run(0.3, image, depth), 1) << "red at the track's depth: re-found";
  EXPECT_NE(run(0.3, green, near), 1) << "nothing at the track's depth: not taken";
}

// A person walking right at 300 px/s hides for 20 frames and comes back where it disappeared
// (it turned round): the constant-velocity prediction is 200 px off, rho is 0, and the method
// starts a new track. With reid_max_distance the coasting track re-finds it by its colours, and
// a differently dressed person appearing at the same spot is not taken for it.
TEST(TrackingKalmanBoxTracker, ReidentificationByAppearanceBridgesADriftedPrediction) {
  auto run = [](double reid, int reappearingColour) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = reid;
    KalmanBoxTracker tracker(params);
    int k = 0;
    for (; k < 10; ++k) step(tracker, k, {dressed(person(100 + 10.f * k, 100, 60, 180, 3.0), 5)});
    for (; k < 30; ++k) step(tracker, k, {});
    const auto tracks =
        step(tracker, k, {dressed(person(190, 100, 60, 180, 3.0), reappearingColour)});
    for (const auto& t : tracks)
      if (t.detection == 0) return t.id;
    return -1;
  };
  EXPECT_NE(run(0.0, 5), 1) << "the method: a new track";
  EXPECT_EQ(run(0.4, 5), 1) << "same colours: re-found";
  EXPECT_NE(run(0.4, 40), 1) << "other colours: not taken";
}

// A confirmed track matched on the last frame that loses its detection is not re-found by
// colour in the same frame: a second person of similar colours stepping out from behind it as
// the detector misses the first one would take its id (a swap bench-tracking found:
// docs/notes/perception.md, 2026-11-28, reid_max_distance). It coasts instead.
TEST(TrackingKalmanBoxTracker, ReidentificationWaitsForATrackToCoast) {
  KalmanBoxTrackerParams params = paperParams();
  params.reid_max_distance = 0.4;
  KalmanBoxTracker tracker(params);
  int k = 0;
  for (; k < 10; ++k) step(tracker, k, {dressed(person(300, 100, 100, 300, 2.0), 5)});
  // The first person missed; another, same colours, 1 m behind, half of it beside the first.
  const auto tracks = step(tracker, k, {dressed(person(350, 140, 80, 240, 3.0), 5)});
  const core::Track* first = findId(tracks, 1);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->detection, -1) << "coasting, not re-found";
}

// A person leaves the image on the right, then walks back in 2 s later (its track was lost when
// its prediction left the view): with reid_memory its new track takes the old id once
// confirmed; someone dressed otherwise gets a new one; without memory the id is new.
TEST(TrackingKalmanBoxTracker, ReidMemoryGivesAReturningPersonItsId) {
  auto run = [](double memory, int returningColour) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = 0.4;
    params.reid_memory = memory;
    KalmanBoxTracker tracker(params);
    int k = 0;
    for (; k < 20; ++k) step(tracker, k, {dressed(person(300 + 10.f * k, 100, 60, 180, 3.0), 7)});
    for (; k < 80; ++k) step(tracker, k, {});  // out of view
    int id = -1;
    for (int n = 0; n < 4; ++n, ++k) {
      const float x = 640 - 60 - 10.f * n;
      for (const auto& t :
           step(tracker, k, {dressed(person(x, 100, 60, 180, 3.0), returningColour)}))
        if (t.detection == 0 && t.state == core::TrackState::Confirmed) id = t.id;
    }
    return std::make_pair(id, tracker.tracksRevived());
  };
  EXPECT_EQ(run(10.0, 7), std::make_pair(1, 1));
  EXPECT_NE(run(10.0, 40).first, 1) << "other colours";
  EXPECT_NE(run(0.0, 7).first, 1) << "no memory";
  EXPECT_NE(run(1.0, 7).first, 1) << "forgotten after 1 s";
}

// A track coasting after its person's measured depth jumped (an arm at the image border): the
// person's new track, once confirmed, takes the coasting track's id, and the coasting one goes.
TEST(TrackingKalmanBoxTracker, ReidMemoryMergesANewTrackIntoACoastingOne) {
  KalmanBoxTrackerParams params = paperParams();
  params.reid_max_distance = 0.4;
  params.reid_memory = 10;
  params.reset_at_border = false;
  KalmanBoxTracker tracker(params);
  int k = 0;
  for (; k < 10; ++k) step(tracker, k, {dressed(person(200, 100, 100, 300, 1.0), 3)});
  std::vector<core::Track> tracks;
  for (int n = 0; n < 3; ++n, ++k)  // depth 1.0 -> 1.6: rho 0.63, below rho_min
    tracks = step(tracker, k, {dressed(person(200, 100, 100, 300, 1.6), 3)});
  ASSERT_EQ(tracks.size(), 1u) << "the coasting track is gone";
  EXPECT_EQ(tracks[0].id, 1);
  EXPECT_EQ(tracks[0].state, core::TrackState::Confirmed);
  EXPECT_EQ(tracks[0].detection, 0);
}

// A returning person's first detections have no descriptor (no depth in its box yet): its new
// track is confirmed without one, and takes the lost track's id once a descriptor comes.
TEST(TrackingKalmanBoxTracker, ReidMemoryWaitsForANewTracksFirstDescriptor) {
  KalmanBoxTrackerParams params = paperParams();
  params.reid_max_distance = 0.4;
  params.reid_memory = 10;
  KalmanBoxTracker tracker(params);
  int k = 0;
  for (; k < 20; ++k) step(tracker, k, {dressed(person(300 + 10.f * k, 100, 60, 180, 3.0), 7)});
  for (; k < 80; ++k) step(tracker, k, {});  // out of view
  std::vector<core::Track> tracks;
  for (int n = 0; n < 6; ++n, ++k) {
    BoxObservation o = person(640 - 60 - 10.f * n, 100, 60, 180, 3.0);
    if (n >= 4) o = dressed(o, 7);
    tracks = step(tracker, k, {o});
    if (n == 3) {
      ASSERT_EQ(tracks.size(), 1u);
      EXPECT_EQ(tracks[0].state, core::TrackState::Confirmed);
      EXPECT_NE(tracks[0].id, 1) << "no descriptor yet";
    }
  }
  ASSERT_EQ(tracks.size(), 1u);
  EXPECT_EQ(tracks[0].id, 1);
  EXPECT_EQ(tracker.tracksRevived(), 1);
}

// The detector misses a near person (green, 0.9 m) for two frames just as a partly hidden one
// steps out beside it and is given its surface (1.0 m): that detection's descriptor, taken in
// the near person's depth band, shows green. Without descriptor_own_surface the new track is
// confirmed with it and reid_memory gives it the near person's id, whose next detection then
// starts a new track; with it the descriptor is not the new track's, and the near person keeps
// its id (as bench-tracking found: docs/notes/perception.md, 2026-11-28, descriptor_own_surface).
TEST(TrackingKalmanBoxTracker, DescriptorsOnAnotherTracksSurfaceAreNotTaken) {
  auto run = [](bool ownSurface) {
    KalmanBoxTrackerParams params = paperParams();
    params.min_hits = 2;
    params.reid_max_distance = 0.4;
    params.reid_memory = 10;
    params.descriptor_own_surface = ownSurface;
    KalmanBoxTracker tracker(params);
    const BoxObservation near = dressed(person(230, 5, 360, 470, 0.9), 3);
    int k = 0;
    for (; k < 10; ++k) step(tracker, k, {near});
    for (int n = 0; n < 2; ++n, ++k) step(tracker, k, {dressed(person(240, 45, 210, 430, 1.0), 3)});
    int nearId = -1, steppingOutId = -1;
    BoxObservation out = person(235, 45, 210, 430, 1.0);  // now without a usable descriptor
    for (const auto& t : step(tracker, k, {near, out})) {
      if (t.detection == 0) nearId = t.id;
      if (t.detection == 1) steppingOutId = t.id;
    }
    return std::make_pair(nearId, steppingOutId);
  };
  EXPECT_EQ(run(false).second, 1) << "without: the near person's id went to the new track";
  EXPECT_EQ(run(true).first, 1) << "the near person keeps its id";
  EXPECT_NE(run(true).second, 1);
}

// Two people of different colours (3 and 9) at one depth, 200 px apart; on frame 10 the
// association gives each track the other's person (here the people change places in one frame,
// as the boxes do at a crossing the depth IoU gets wrong). Each track's running descriptor then
// turns to the other's colours while its identity descriptor stays: with identity_check the ids
// go back to the people within a few frames.
TEST(TrackingKalmanBoxTracker, IdentityCheckSwapsIdsBackAfterAnAssociationSwappedThem) {
  auto idOfColour3 = [](double identityCheck) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = 0.4;
    params.identity_check = identityCheck;
    KalmanBoxTracker tracker(params);
    int k = 0;
    std::vector<core::Track> tracks;
    for (; k < 10; ++k)
      step(
          tracker, k,
          {dressed(person(200, 100, 60, 180, 3.0), 3), dressed(person(400, 100, 60, 180, 3.0), 9)});
    for (; k < 20; ++k)
      tracks = step(
          tracker, k,
          {dressed(person(200, 100, 60, 180, 3.0), 9), dressed(person(400, 100, 60, 180, 3.0), 3)});
    for (const auto& t : tracks)
      if (t.detection == 1) return std::make_pair(t.id, tracker.identitiesSwapped());
    return std::make_pair(-1, tracker.identitiesSwapped());
  };
  ASSERT_EQ(idOfColour3(0.0).first, 2) << "without: the ids stay with the boxes";
  EXPECT_EQ(idOfColour3(0.1).first, 1) << "colour 3 was track 1";
  EXPECT_EQ(idOfColour3(0.1).second, 1) << "swapped once, not back and forth";
}

// Two people of different colours (3 and 9); the one in colour 9 (track 2) goes out of sight and
// its track is lost and remembered; from frame 15 the association gives track 1 that person
// where the person in colour 3 was (track 1's person left unseen, as when a swap lands a track
// on a person whose own track was lost). The pair check has nothing to compare with: with
// identity_repair, after that many views off its identity track 1 takes the lost id whose
// identity its views match. A colour nobody had leaves the id alone.
TEST(TrackingKalmanBoxTracker, IdentityRepairGivesATrackTheLostIdOfThePersonItFollows) {
  auto idAfter = [](int repair, int newColour) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = 0.4;
    params.reid_memory = 10;
    params.identity_check = 0.1;
    params.identity_repair = repair;
    params.max_age = 3;
    KalmanBoxTracker tracker(params);
    int k = 0;
    for (; k < 10; ++k)
      step(
          tracker, k,
          {dressed(person(200, 100, 60, 180, 3.0), 3), dressed(person(400, 100, 60, 180, 3.0), 9)});
    for (; k < 15; ++k) step(tracker, k, {dressed(person(200, 100, 60, 180, 3.0), 3)});
    std::vector<core::Track> tracks;
    for (; k < 30; ++k)
      tracks = step(tracker, k, {dressed(person(200, 100, 60, 180, 3.0), newColour)});
    return tracks.size() == 1 ? std::make_pair(tracks[0].id, tracker.identitiesRepaired())
                              : std::make_pair(-1, -1);
  };
  ASSERT_EQ(idAfter(0, 9).first, 1) << "without: the track keeps the id it had";
  EXPECT_EQ(idAfter(5, 9), std::make_pair(2, 1)) << "colour 9's id, given once";
  EXPECT_EQ(idAfter(5, 20).first, 1) << "a colour no lost track had";
}

// Two people whose colours are alike (half of each descriptor in one shared bin: distance 0.71).
// A is missed just as B stands where A was, so A's track 1 takes B (the association swapped
// them, as at a crossing), and B's track 2 is lost and remembered. A comes back elsewhere: its
// new track, once confirmed, is revived into id 2, the only one within reid_max_distance. Each
// id now sits on the other's person. When the revived track takes over id 2's identity
// descriptor (9 views of B: a new track takes none on its first frame), identity_check sees each
// track's views match the other's identity and swaps the ids back; when it keeps its own first
// views as identity, both identities describe A and nothing tells (as bench-tracking found:
// docs/notes/perception.md, 2026-11-28, revival_takes_identity). revival_takes_identity = 30 asks
// for more views than id 2's identity took.
TEST(TrackingKalmanBoxTracker, ARevivedIdKeepsItsIdentitySoAWrongRevivalIsSwappedBack) {
  auto dressedAlike = [](BoxObservation o, int bin) {
    o.appearance = cv::Mat::zeros(1, kAppearanceBins, CV_32F);
    o.appearance.at<float>(3) = 0.5f;
    o.appearance.at<float>(bin) = 0.5f;
    return o;
  };
  auto idsOfAAndB = [&](int takesIdentity) {
    KalmanBoxTrackerParams params = paperParams();
    params.reid_max_distance = 0.75;
    params.reid_memory = 10;
    params.identity_check = 0.1;
    params.max_age = 3;
    params.revival_takes_identity = takesIdentity;
    KalmanBoxTracker tracker(params);
    auto a = [&](float x) { return dressedAlike(person(x, 100, 60, 180, 3.0), 5); };
    auto b = [&](float x) { return dressedAlike(person(x, 100, 60, 180, 3.0), 9); };
    int k = 0;
    for (; k < 10; ++k) step(tracker, k, {a(200), b(400)});
    for (; k < 15; ++k) step(tracker, k, {b(200)});
    std::vector<core::Track> tracks;
    for (; k < 25; ++k) tracks = step(tracker, k, {b(200), a(500)});
    int idA = -1, idB = -1;
    for (const auto& t : tracks) {
      if (t.detection == 0) idB = t.id;
      if (t.detection == 1) idA = t.id;
    }
    return std::make_pair(idA, idB);
  };
  ASSERT_EQ(idsOfAAndB(0), std::make_pair(2, 1)) << "without: each on the other's id";
  EXPECT_EQ(idsOfAAndB(5), std::make_pair(1, 2));
  EXPECT_EQ(idsOfAAndB(30), std::make_pair(2, 1)) << "too young an identity to take";
}
