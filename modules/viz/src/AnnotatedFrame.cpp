#include "dynslam/viz/AnnotatedFrame.h"

#include "dynslam/viz/IdColours.h"

#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <string>

namespace dynslam::viz {
namespace {

cv::Mat baseImage(const core::Frame& f) {
  if (!f.rgb.empty()) return f.rgb.clone();
  cv::Mat out;
  if (!f.depth.empty()) {
    cv::Mat grey;
    f.depth.convertTo(grey, CV_8UC1, 255.0 / 5.0);  // 0-5 m
    cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
    return out;
  }
  return cv::Mat(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
}

/// Text with a dark outline so it reads on any background.
void label(cv::Mat& img, const std::string& text, cv::Point at, const cv::Scalar& colour,
           double scale) {
  at.y = std::max(at.y, 12);
  cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, {0, 0, 0}, 3, cv::LINE_AA);
  cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

std::string fixed(const char* format, double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

}  // namespace

cv::Scalar featureClassColour(core::FeatureClass feature_class) {
  switch (feature_class) {
    case core::FeatureClass::Static:
      return {80, 220, 80};
    case core::FeatureClass::Rigid:
      return {0, 160, 255};
    case core::FeatureClass::NonRigid:
      return {255, 0, 255};
  }
  return {255, 255, 255};
}

namespace {

/// Each object mask tinted in its track's colour (its detection's when no track owns it).
void drawMasks(cv::Mat& img, const core::Frame& f, double alpha) {
  const cv::Rect whole(0, 0, img.cols, img.rows);
  // Which track owns each detection, for the mask colours.
  std::vector<int> trackOf(f.detections.size(), 0);
  for (const auto& t : f.tracks)
    if (t.detection >= 0 && t.detection < static_cast<int>(trackOf.size()))
      trackOf[static_cast<size_t>(t.detection)] = t.id;
  for (const auto& m : f.object_masks) {
    const cv::Rect roi = m.roi & whole;
    if (!m.valid || m.mask.empty() || roi.empty() || roi.size() != m.mask.size()) continue;
    const bool known = m.detection >= 0 && m.detection < static_cast<int>(trackOf.size());
    const int id = known && trackOf[static_cast<size_t>(m.detection)] > 0
                       ? trackOf[static_cast<size_t>(m.detection)]
                       : 1000 + m.detection;
    cv::Mat patch = img(roi), tinted;
    cv::addWeighted(patch, 1.0 - alpha, cv::Mat(patch.size(), CV_8UC3, colourForId(id)), alpha, 0.0,
                    tinted);
    tinted.copyTo(patch, m.mask);
  }
}

void drawTracks(cv::Mat& img, const core::Frame& f, double font_scale) {
  for (const auto& t : f.tracks) {
    if (t.state == core::TrackState::Lost) continue;
    const cv::Scalar colour = colourForId(t.id);
    const bool coasting = t.detection < 0;
    cv::rectangle(img, t.box, colour, coasting ? 1 : 2, cv::LINE_AA);
    // A coasting track says its id only: far crowds coast by the dozen (outdoor_street_high
    // frame 190: 57 tracks) and their full labels covered the picture.
    std::string text = "#" + std::to_string(t.id);
    if (coasting)
      text += " ~";
    else
      text += " " + t.category + (t.depth > 0 ? fixed(" d=%.2fm", t.depth) : " no depth");
    if (t.state == core::TrackState::Tentative) text += " ?";
    label(img, text, {static_cast<int>(t.box.x), static_cast<int>(t.box.y) - 4}, colour,
          font_scale);
  }
}

}  // namespace

cv::Mat renderAnnotatedFrame(const core::Frame& f, const AnnotationOptions& o) {
  cv::Mat img = baseImage(f);
  if (o.mask_alpha > 0) drawMasks(img, f, o.mask_alpha);
  if (o.detections)
    for (const auto& d : f.detections) {
      cv::rectangle(img, d.box, {200, 200, 200}, 1, cv::LINE_AA);
      label(img, d.category + fixed(" %.2f", d.score),
            {static_cast<int>(d.box.x), static_cast<int>(d.box.y + d.box.height) + 12},
            {200, 200, 200}, o.font_scale * 0.85);
    }
  if (o.tracks) drawTracks(img, f, o.font_scale);
  if (o.features)
    for (const auto& feature : f.features)
      cv::circle(img, feature.pixel, 2, featureClassColour(feature.feature_class), cv::FILLED,
                 cv::LINE_AA);

  char header[160];
  std::snprintf(
      header, sizeof header, "frame %zu  t=%.3f s  %zu detections%s  %zu tracks%s", f.index, f.t,
      f.detections.size(), f.detections_fresh ? "" : " (none fresh)", f.tracks.size(),
      f.features.empty() ? "" : ("  " + std::to_string(f.features.size()) + " features").c_str());
  label(img, header, {6, 16}, {255, 255, 255}, o.font_scale);
  return img;
}

}  // namespace dynslam::viz
