#include <dynslam/viz/AnnotatedFrame.h>
#include <dynslam/viz/IdColours.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace dynslam;

namespace {

core::Frame frameWithOnePerson() {
  core::Frame f;
  f.index = 7;
  f.t = 1.5;
  f.rgb = cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90));
  core::Detection d;
  d.box = cv::Rect2f(100, 60, 60, 120);
  d.category = "person";
  d.score = 0.9f;
  f.detections = {d};
  f.detections_fresh = true;
  core::ObjectMask m;
  m.detection = 0;
  m.roi = cv::Rect(100, 60, 60, 120);
  m.mask = cv::Mat(120, 60, CV_8UC1, cv::Scalar(0));
  m.mask(cv::Rect(10, 10, 40, 100)).setTo(255);
  m.valid = true;
  f.object_masks = {m};
  core::Track t;
  t.id = 4;
  t.state = core::TrackState::Confirmed;
  t.box = d.box;
  t.depth = 2.3;
  t.category = "person";
  t.detection = 0;
  f.tracks = {t};
  return f;
}

}  // namespace

TEST(IdColours, StableDistinctAndVisible) {
  EXPECT_EQ(viz::colourForId(0), cv::Scalar(0, 0, 0));
  EXPECT_EQ(viz::colourForId(5), viz::colourForId(5));
  EXPECT_NE(viz::colourForId(5), viz::colourForId(6));
  for (int id = 1; id < 50; ++id)
    for (int c = 0; c < 3; ++c) EXPECT_GE(viz::colourForId(id)[c], 64) << id;
}

TEST(AnnotatedFrame, MaskTintedInTheTrackColourBackgroundUntouched) {
  const core::Frame f = frameWithOnePerson();
  const cv::Mat img = viz::renderAnnotatedFrame(f);
  ASSERT_EQ(img.size(), f.rgb.size());
  ASSERT_EQ(img.type(), CV_8UC3);
  // Inside the mask (away from box lines and text) the pixel moved towards the track colour.
  const cv::Vec3b inside = img.at<cv::Vec3b>(130, 130);
  const cv::Scalar colour = viz::colourForId(4);
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.55 * 90 + 0.45 * colour[c];
    EXPECT_NEAR(inside[c], expected, 1.5) << c;
  }
  // Inside the box but outside the mask: the original grey.
  EXPECT_EQ(img.at<cv::Vec3b>(175, 104), cv::Vec3b(90, 90, 90));
  // Far from everything: untouched; the track box is drawn in its colour.
  EXPECT_EQ(img.at<cv::Vec3b>(220, 300), cv::Vec3b(90, 90, 90));
  const cv::Vec3b edge = img.at<cv::Vec3b>(120, 100);
  EXPECT_NE(edge, cv::Vec3b(90, 90, 90)) << "the box outline";
}

// A coasting track's label is its id alone: the text above its box covers a fraction of the
// width a matched track's "#4 person d=2.30m" covers.
TEST(AnnotatedFrame, CoastingTracksAreLabelledByTheirIdOnly) {
  auto labelWidth = [](bool coasting) {
    core::Frame f = frameWithOnePerson();
    f.detections.clear();
    f.object_masks.clear();
    if (coasting) f.tracks[0].detection = -1;
    viz::AnnotationOptions o;
    o.features = false;
    const cv::Mat img = viz::renderAnnotatedFrame(f, o);
    int right = -1;  // the rightmost column the label changed, rows just above the box
    for (int y = 44; y < 58; ++y)
      for (int x = 100; x < img.cols; ++x)
        if (img.at<cv::Vec3b>(y, x) != cv::Vec3b(90, 90, 90)) right = std::max(right, x);
    return right - 100;
  };
  const int matched = labelWidth(false), coasting = labelWidth(true);
  EXPECT_GT(matched, 100) << "#4 person d=2.30m";
  EXPECT_GT(coasting, 5);
  EXPECT_LT(coasting, matched / 3);
}

TEST(AnnotatedFrame, DrawsOnDepthWhenThereIsNoColour) {
  core::Frame f;
  f.depth = cv::Mat(120, 160, CV_32FC1, cv::Scalar(2.5f));
  const cv::Mat img = viz::renderAnnotatedFrame(f);
  EXPECT_EQ(img.size(), cv::Size(160, 120));
  EXPECT_EQ(img.at<cv::Vec3b>(100, 150), cv::Vec3b(128, 128, 128)) << "2.5 m of 0-5 m";
  EXPECT_EQ(viz::renderAnnotatedFrame(core::Frame{}).size(), cv::Size(640, 480));
}

TEST(AnnotatedFrame, FeaturesColouredByClass) {
  core::Frame f;
  f.rgb = cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 90, 90));
  const core::FeatureClass classes[] = {core::FeatureClass::Static, core::FeatureClass::Rigid,
                                        core::FeatureClass::NonRigid};
  for (int i = 0; i < 3; ++i) {
    core::Feature feature;
    feature.pixel = cv::Point2f(40.f + 40.f * i, 80.f);
    feature.feature_class = classes[i];
    f.features.push_back(feature);
  }
  const cv::Mat img = viz::renderAnnotatedFrame(f);
  for (int i = 0; i < 3; ++i) {
    const cv::Scalar c = viz::featureClassColour(classes[i]);
    EXPECT_EQ(img.at<cv::Vec3b>(80, 40 + 40 * i), cv::Vec3b(c[0], c[1], c[2])) << i;
  }
  EXPECT_NE(viz::featureClassColour(core::FeatureClass::Static),
            viz::featureClassColour(core::FeatureClass::NonRigid));
  viz::AnnotationOptions off;
  off.features = false;
  EXPECT_EQ(viz::renderAnnotatedFrame(f, off).at<cv::Vec3b>(80, 40), cv::Vec3b(90, 90, 90));
}
