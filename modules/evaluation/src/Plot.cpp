#include "dynslam/evaluation/Plot.h"

#include "dynslam/evaluation/EvaluationError.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

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

/// Horizontal grid lines, ticks and labels of the vertical axis, the panel's frame and the
/// axis title (written horizontally above the axis: OpenCV has no rotated text).
void drawYAxis(cv::Mat& img, const Axis& x, const Axis& y, const std::string& y_title) {
  const cv::Rect frame(cv::Point(x.px_lo, y.px_hi), cv::Point(x.px_hi, y.px_lo));
  const double y_step = niceStep(y.hi - y.lo, 6);
  for (double v = std::ceil(y.lo / y_step) * y_step; v <= y.hi + 1e-9 * y_step; v += y_step) {
    const int py = static_cast<int>(std::lround(y.toPixel(v)));
    cv::line(img, {frame.x, py}, {frame.x + frame.width, py}, kGrid, 1);
    cv::line(img, {x.px_lo - 5, py}, {x.px_lo, py}, kBlack, 1);
    const std::string label = formatTick(v, y_step);
    putLabel(img, label, {x.px_lo - 8 - textWidth(label), py + 5});
  }
  cv::rectangle(img, frame, kBlack, 1);
  putLabel(img, y_title, {std::max(4, x.px_lo - 60), y.px_hi - 6}, 0.5);
}

/// Grid, ticks with labels and axis titles of one panel; `x`/`y` carry the pixel intervals.
void drawAxes(cv::Mat& img, const Axis& x, const Axis& y, const std::string& x_title,
              const std::string& y_title) {
  const double x_step = niceStep(x.hi - x.lo, 8);
  for (double v = std::ceil(x.lo / x_step) * x_step; v <= x.hi + 1e-9 * x_step; v += x_step) {
    const int px = static_cast<int>(std::lround(x.toPixel(v)));
    cv::line(img, {px, y.px_hi}, {px, y.px_lo}, kGrid, 1);
    cv::line(img, {px, y.px_lo}, {px, y.px_lo + 5}, kBlack, 1);
    const std::string label = formatTick(v, x_step);
    putLabel(img, label, {px - textWidth(label) / 2, y.px_lo + 20});
  }
  drawYAxis(img, x, y, y_title);
  putLabel(img, x_title, {(x.px_lo + x.px_hi - textWidth(x_title, 0.5)) / 2, y.px_lo + 45}, 0.5);
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

/// Colours of a bar chart's series, in order (BGR; saturated, so that no bar is mistaken for
/// the grid or the text).
const cv::Scalar kSeriesColours[] = {{60, 60, 200}, {30, 150, 240}, {200, 110, 20},
                                     {60, 160, 60}, {160, 70, 160}, {150, 150, 20}};

/// `text` on one line, or on two split at the '_' or ' ' nearest its middle when it is wider
/// than `width` pixels.
std::vector<std::string> fitLabel(const std::string& text, int width) {
  if (textWidth(text) <= width) return {text};
  std::size_t best = std::string::npos;
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((text[i] == '_' || text[i] == ' ') &&
        (best == std::string::npos ||
         std::abs(2.0 * i - text.size()) < std::abs(2.0 * best - text.size())))
      best = i;
  if (best == std::string::npos) return {text};
  return {text.substr(0, best + 1), text.substr(best + 1)};
}

void writePng(const std::string& path, const cv::Mat& img) {
  bool written = false;
  try {
    written = cv::imwrite(path, img);
  } catch (const cv::Exception& e) {
    throw EvaluationError("cannot write plot '" + path + "': " + e.what());
  }
  if (!written) throw EvaluationError("cannot write plot '" + path + "'");
}

constexpr int kBarChartHeight = 560, kLegendRow = 20;

/// Checks the table's shape and values; returns the largest value (1 when none is > 0).
double barChartTop(const BarChartInput& in) {
  if (in.groups.empty() || in.series.empty())
    throw EvaluationError("bar chart: no group or no series to draw");
  if (in.series.size() > std::size(kSeriesColours))
    throw EvaluationError("bar chart: at most " + std::to_string(std::size(kSeriesColours)) +
                          " series");
  if (in.values.size() != in.groups.size())
    throw EvaluationError("bar chart: " + std::to_string(in.values.size()) +
                          " rows of values for " + std::to_string(in.groups.size()) + " groups");
  double top = 0;
  for (std::size_t g = 0; g < in.values.size(); ++g) {
    if (in.values[g].size() != in.series.size())
      throw EvaluationError("bar chart: group '" + in.groups[g] + "' has " +
                            std::to_string(in.values[g].size()) + " values for " +
                            std::to_string(in.series.size()) + " series");
    for (double v : in.values[g])
      if (std::isfinite(v)) {
        if (v < 0)
          throw EvaluationError("bar chart: negative value in group '" + in.groups[g] + "'");
        top = std::max(top, v);
      }
  }
  return top > 0 ? top : 1;
}

/// Group g's bars with their values above them, and its name (wrapped) below the baseline.
void drawBarGroup(cv::Mat& img, const BarChartInput& in, std::size_t g, const Axis& x,
                  const Axis& y, int group_px, int bar_px) {
  const int left = x.px_lo + static_cast<int>(g) * group_px +
                   (group_px - bar_px * static_cast<int>(in.series.size())) / 2;
  for (std::size_t k = 0; k < in.series.size(); ++k) {
    const double v = in.values[g][k];
    const int bx = left + static_cast<int>(k) * bar_px;
    if (!std::isfinite(v)) {  // a missing value: no bar, a dash on the baseline
      putLabel(img, "-", {bx + (bar_px - textWidth("-")) / 2, y.px_lo - 4});
      continue;
    }
    const int py = static_cast<int>(std::lround(y.toPixel(v)));
    cv::rectangle(img, cv::Point(bx + 1, py), cv::Point(bx + bar_px - 2, y.px_lo - 1),
                  kSeriesColours[k], cv::FILLED);
    char label[32];
    std::snprintf(label, sizeof label, "%.3g", v);
    const double scale = textWidth(label, 0.4) <= bar_px - 2 ? 0.4 : 0.32;
    // A label wider than its bar would run into its neighbour's: every other one goes a line up.
    const int lift = textWidth(label, scale) > bar_px - 2 && k % 2 == 1 ? 12 : 0;
    putLabel(img, label, {bx + (bar_px - textWidth(label, scale)) / 2, py - 4 - lift}, scale);
  }
  const auto lines = fitLabel(in.groups[g], group_px - 6);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const int centre = x.px_lo + static_cast<int>(g) * group_px + group_px / 2;
    putLabel(img, lines[l],
             {centre - textWidth(lines[l]) / 2, y.px_lo + 20 + 18 * static_cast<int>(l)});
  }
}

/// Legend in the upper right corner, above the bars.
void drawBarLegend(cv::Mat& img, const BarChartInput& in, const Axis& x, int plot_top,
                   int legend_height) {
  int legend_width = 0;
  for (const auto& name : in.series) legend_width = std::max(legend_width, textWidth(name));
  const cv::Rect box(x.px_hi - legend_width - 50, plot_top, legend_width + 40, legend_height - 6);
  cv::rectangle(img, box, kBlack, 1);
  for (std::size_t k = 0; k < in.series.size(); ++k) {
    const int row = box.y + 6 + kLegendRow * static_cast<int>(k);
    cv::rectangle(img, cv::Rect(box.x + 8, row + 2, 12, 12), kSeriesColours[k], cv::FILLED);
    putLabel(img, in.series[k], {box.x + 28, row + 13});
  }
}

}  // namespace

void writeBarChartPng(const std::string& path, const BarChartInput& in) {
  const double top = barChartTop(in);
  const int legend_height = kLegendRow * static_cast<int>(in.series.size()) + 10;
  cv::Mat img(kTitleHeight + kBarChartHeight, kWidth, CV_8UC3, kWhite);
  putLabel(img, in.title, {kMarginLeft, 28}, 0.6, kBlack, 1);
  // Bars start at zero; the top leaves room for the value labels and the legend.
  const Axis x{0, 1, kMarginLeft, kWidth - kMarginRight};
  const int plot_top = kTitleHeight + kMarginTop + 10;
  const Axis y{0, top * 1.12, kTitleHeight + kBarChartHeight - kMarginBottom,
               plot_top + legend_height};
  drawYAxis(img, x, y, in.value_label);

  const int group_px = (x.px_hi - x.px_lo) / static_cast<int>(in.groups.size());
  const int bar_px = std::max(2, group_px * 4 / 5 / static_cast<int>(in.series.size()));
  for (std::size_t g = 0; g < in.groups.size(); ++g)
    drawBarGroup(img, in, g, x, y, group_px, bar_px);
  drawBarLegend(img, in, x, plot_top, legend_height);
  writePng(path, img);
}

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
  writePng(path, img);
}

}  // namespace dynslam::evaluation
