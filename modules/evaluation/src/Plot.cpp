#include "dynslam/evaluation/Plot.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dynslam::evaluation {
namespace {

constexpr int kWidth = 1000;
constexpr int kTitleHeight = 40;
constexpr int kTopHeight = 720;
constexpr int kBottomHeight = 340;
constexpr int kMarginLeft = 80, kMarginRight = 30, kMarginTop = 20, kMarginBottom = 55;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

const cv::Scalar kWhite(255, 255, 255), kBlack(0, 0, 0), kGrid(225, 225, 225);
const cv::Scalar kReferenceColour(80, 80, 80);   // dark grey (BGR)
const cv::Scalar kEstimateColour(200, 110, 20);  // blue
const cv::Scalar kErrorColour(40, 40, 210);      // red
const cv::Scalar kMeanColour(40, 160, 40);       // green

/// A data range mapped onto a pixel interval; y grows upwards in data, downwards in pixels.
struct Axis {
  double lo = 0.0, hi = 1.0;
  int px_lo = 0, px_hi = 1;
  double toPixel(double v) const { return px_lo + (v - lo) / (hi - lo) * (px_hi - px_lo); }
};

/// A 1-2-5 tick step giving about `target` intervals over `span`.
double niceStep(double span, int target) {
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalised = raw / magnitude;
  const double nice = normalised < 1.5   ? 1.0
                      : normalised < 3.5 ? 2.0
                      : normalised < 7.5 ? 5.0
                                         : 10.0;
  return nice * magnitude;
}

std::string formatTick(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(value) < step * 1e-6 ? 0.0 : value);
  return buf;
}

void putLabel(cv::Mat& img, const std::string& text, cv::Point at, double scale = 0.45,
              const cv::Scalar& colour = kBlack, int thickness = 1) {
  cv::putText(img, text, at, kFont, scale, colour, thickness, cv::LINE_AA);
}

int textWidth(const std::string& text, double scale = 0.45) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, 1, &baseline).width;
}

/// Grid, ticks with labels and axis titles of one panel; `x`/`y` carry the pixel intervals.
void drawAxes(cv::Mat& img, const Axis& x, const Axis& y, const std::string& x_title,
              const std::string& y_title) {
  const cv::Rect frame(cv::Point(x.px_lo, y.px_hi), cv::Point(x.px_hi, y.px_lo));
  const double x_step = niceStep(x.hi - x.lo, 8), y_step = niceStep(y.hi - y.lo, 6);
  for (double v = std::ceil(x.lo / x_step) * x_step; v <= x.hi + 1e-9 * x_step; v += x_step) {
    const int px = static_cast<int>(std::lround(x.toPixel(v)));
    cv::line(img, {px, frame.y}, {px, frame.y + frame.height}, kGrid, 1);
    cv::line(img, {px, y.px_lo}, {px, y.px_lo + 5}, kBlack, 1);
    const std::string label = formatTick(v, x_step);
    putLabel(img, label, {px - textWidth(label) / 2, y.px_lo + 20});
  }
  for (double v = std::ceil(y.lo / y_step) * y_step; v <= y.hi + 1e-9 * y_step; v += y_step) {
    const int py = static_cast<int>(std::lround(y.toPixel(v)));
    cv::line(img, {frame.x, py}, {frame.x + frame.width, py}, kGrid, 1);
    cv::line(img, {x.px_lo - 5, py}, {x.px_lo, py}, kBlack, 1);
    const std::string label = formatTick(v, y_step);
    putLabel(img, label, {x.px_lo - 8 - textWidth(label), py + 5});
  }
  cv::rectangle(img, frame, kBlack, 1);
  putLabel(img, x_title, {(x.px_lo + x.px_hi - textWidth(x_title, 0.5)) / 2, y.px_lo + 45}, 0.5);
  // Vertical axis title written horizontally above the axis: OpenCV has no rotated text.
  putLabel(img, y_title, {std::max(4, x.px_lo - 60), y.px_hi - 6}, 0.5);
}

/// Extends [lo, hi] by a margin and guards against a zero span.
void pad(double& lo, double& hi, double fraction) {
  double span = hi - lo;
  if (!(span > 1e-9)) {
    const double centre = 0.5 * (lo + hi);
    lo = centre - 0.5;
    hi = centre + 0.5;
    span = 1.0;
  }
  lo -= fraction * span;
  hi += fraction * span;
}

cv::Point2d planeCoords(const core::StampedPose& pose, PlotPlane plane) {
  const Eigen::Vector3d p = pose.T_world_body.translation();
  switch (plane) {
    case PlotPlane::XY:
      return {p.x(), p.y()};
    case PlotPlane::XZ:
      return {p.x(), p.z()};
    case PlotPlane::YZ:
      return {p.y(), p.z()};
  }
  return {p.x(), p.y()};
}

void drawPolyline(cv::Mat& img, const std::vector<cv::Point2d>& pts, const Axis& x, const Axis& y,
                  const cv::Scalar& colour, int thickness) {
  std::vector<cv::Point> pixels;
  pixels.reserve(pts.size());
  for (const auto& p : pts)
    pixels.emplace_back(static_cast<int>(std::lround(x.toPixel(p.x))),
                        static_cast<int>(std::lround(y.toPixel(p.y))));
  if (pixels.size() == 1) cv::circle(img, pixels.front(), 2, colour, cv::FILLED, cv::LINE_AA);
  cv::polylines(img, pixels, false, colour, thickness, cv::LINE_AA);
}

void drawTopView(cv::Mat& img, const PlotInput& in, int top) {
  const char* names[3][2] = {{"x (m)", "y (m)"}, {"x (m)", "z (m)"}, {"y (m)", "z (m)"}};
  const auto& axis_names = names[static_cast<int>(in.plane)];
  std::vector<cv::Point2d> ref, est;
  for (const auto& p : in.reference) ref.push_back(planeCoords(p, in.plane));
  for (const auto& p : in.estimate) est.push_back(planeCoords(p, in.plane));

  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  for (const auto* pts : {&ref, &est})
    for (const auto& p : *pts) {
      x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
      y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    }
  pad(x_lo, x_hi, 0.05);
  pad(y_lo, y_hi, 0.05);

  // Same metres per pixel on both axes, so that the path keeps its true shape.
  const int px_w = kWidth - kMarginLeft - kMarginRight;
  const int px_h = kTopHeight - kMarginTop - kMarginBottom;
  const double scale = std::min(px_w / (x_hi - x_lo), px_h / (y_hi - y_lo));
  const double x_mid = 0.5 * (x_lo + x_hi), y_mid = 0.5 * (y_lo + y_hi);
  Axis x{x_mid - 0.5 * px_w / scale, x_mid + 0.5 * px_w / scale, kMarginLeft, kMarginLeft + px_w};
  Axis y{y_mid - 0.5 * px_h / scale, y_mid + 0.5 * px_h / scale, top + kTopHeight - kMarginBottom,
         top + kMarginTop};
  drawAxes(img, x, y, axis_names[0], axis_names[1]);
  drawPolyline(img, ref, x, y, kReferenceColour, 3);
  drawPolyline(img, est, x, y, kEstimateColour, 1);

  // Legend in the upper left corner of the panel.
  const cv::Rect box(kMarginLeft + 10, top + kMarginTop + 10, 210, 52);
  cv::rectangle(img, box, kWhite, cv::FILLED);
  cv::rectangle(img, box, kBlack, 1);
  cv::line(img, {box.x + 10, box.y + 17}, {box.x + 40, box.y + 17}, kReferenceColour, 2,
           cv::LINE_AA);
  putLabel(img, "reference", {box.x + 50, box.y + 22});
  cv::line(img, {box.x + 10, box.y + 37}, {box.x + 40, box.y + 37}, kEstimateColour, 2,
           cv::LINE_AA);
  putLabel(img, "estimate (aligned)", {box.x + 50, box.y + 42});
}

void drawErrorPlot(cv::Mat& img, const PlotInput& in, int top) {
  double t_lo = *std::min_element(in.error_times.begin(), in.error_times.end());
  double t_hi = *std::max_element(in.error_times.begin(), in.error_times.end());
  double e_hi = *std::max_element(in.errors.begin(), in.errors.end());
  double e_lo = std::min(0.0, *std::min_element(in.errors.begin(), in.errors.end()));
  pad(t_lo, t_hi, 0.0);
  pad(e_lo, e_hi, 0.05);
  Axis x{t_lo, t_hi, kMarginLeft, kWidth - kMarginRight};
  Axis y{e_lo, e_hi, top + kBottomHeight - kMarginBottom, top + kMarginTop + 10};
  drawAxes(img, x, y, in.time_label, in.error_label);

  std::vector<cv::Point2d> pts;
  for (std::size_t i = 0; i < in.errors.size(); ++i)
    pts.emplace_back(in.error_times[i], in.errors[i]);
  drawPolyline(img, pts, x, y, kErrorColour, 1);

  double mean = 0.0;
  for (double e : in.errors) mean += e;
  mean /= static_cast<double>(in.errors.size());
  const int py = static_cast<int>(std::lround(y.toPixel(mean)));
  for (int px = x.px_lo; px < x.px_hi; px += 12)
    cv::line(img, {px, py}, {std::min(px + 6, x.px_hi), py}, kMeanColour, 1);
  char label[64];
  std::snprintf(label, sizeof label, "mean %.4g", mean);
  putLabel(img, label, {x.px_hi - textWidth(label) - 6, py - 6}, 0.45, kMeanColour);
}

}  // namespace

PlotPlane parsePlotPlane(const std::string& name) {
  if (name == "xy") return PlotPlane::XY;
  if (name == "xz") return PlotPlane::XZ;
  if (name == "yz") return PlotPlane::YZ;
  throw std::invalid_argument("unknown plot plane '" + name + "' (expected xy, xz or yz)");
}

void writePlotPng(const std::string& path, const PlotInput& in) {
  if (in.reference.empty() || in.estimate.empty())
    throw EvaluationError("plot: no trajectory to draw");
  if (in.errors.empty() || in.errors.size() != in.error_times.size())
    throw EvaluationError("plot: error samples and their times must be non-empty and paired");

  cv::Mat img(kTitleHeight + kTopHeight + kBottomHeight, kWidth, CV_8UC3, kWhite);
  putLabel(img, in.title, {kMarginLeft, 28}, 0.6, kBlack, 1);
  drawTopView(img, in, kTitleHeight);
  drawErrorPlot(img, in, kTitleHeight + kTopHeight);

  bool written = false;
  try {
    written = cv::imwrite(path, img);
  } catch (const cv::Exception& e) {
    throw EvaluationError("cannot write plot '" + path + "': " + e.what());
  }
  if (!written) throw EvaluationError("cannot write plot '" + path + "'");
}

}  // namespace dynslam::evaluation
