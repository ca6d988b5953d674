#include "sweep/SweepPlot.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::sweep {
namespace {

constexpr int kWidth = 900, kHeight = 560;
constexpr int kLeft = 90, kRight = 260, kTop = 50, kBottom = 70;  // the legend sits right
constexpr size_t kMaxSeries = 8;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kBlack(0, 0, 0), kGrid(225, 225, 225), kWhite(255, 255, 255);

cv::Scalar seriesColour(size_t i) {
  static const cv::Scalar palette[] = {{180, 119, 31},  {14, 127, 255},  {44, 160, 44},
                                       {40, 39, 214},   {189, 103, 148}, {75, 86, 140},
                                       {194, 119, 227}, {127, 127, 127}};
  return palette[i % 8];
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Numeric positions when every value is a number, evenly spaced categories otherwise.
std::vector<double> xPositions(const std::vector<std::string>& values, bool& numeric) {
  std::vector<double> x;
  numeric = true;
  for (const auto& v : values) {
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    numeric = numeric && end == v.c_str() + v.size() && std::isfinite(d);
    x.push_back(d);
  }
  if (!numeric)
    for (size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
  return x;
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.45) {
  cv::putText(img, s, at, kFont, scale, kBlack, 1, cv::LINE_AA);
}

struct Series {
  std::string label;
  std::vector<double> y;       ///< per value of the plotted key; NaN where nothing was scored
  std::vector<double> lo, hi;  ///< band (median-of-series mode only)
};

void draw(const std::string& path, const std::string& title, const std::string& xLabel,
          const std::vector<std::string>& values, const std::vector<Series>& series) {
  bool numeric = true;
  const std::vector<double> x = xPositions(values, numeric);
  double xlo = *std::min_element(x.begin(), x.end()), xhi = *std::max_element(x.begin(), x.end());
  double ylo = std::numeric_limits<double>::infinity(), yhi = -ylo;
  for (const auto& s : series)
    for (size_t i = 0; i < s.y.size(); ++i) {
      for (double v : {s.y[i], s.lo.empty() ? s.y[i] : s.lo[i], s.hi.empty() ? s.y[i] : s.hi[i]})
        if (std::isfinite(v)) ylo = std::min(ylo, v), yhi = std::max(yhi, v);
    }
  if (xhi - xlo <= 0) xlo -= 0.5, xhi += 0.5;
  const double ypad = yhi > ylo ? 0.08 * (yhi - ylo) : std::max(1e-3, 0.1 * std::abs(yhi));
  ylo = std::max(0.0, ylo - ypad), yhi += ypad;
  const double xpad = 0.05 * (xhi - xlo);
  xlo -= xpad, xhi += xpad;

  cv::Mat img(kHeight, kWidth, CV_8UC3, kWhite);
  const int px0 = kLeft, px1 = kWidth - kRight, py0 = kHeight - kBottom, py1 = kTop;
  auto toPx = [&](double vx, double vy) {
    return cv::Point(static_cast<int>(std::lround(px0 + (vx - xlo) / (xhi - xlo) * (px1 - px0))),
                     static_cast<int>(std::lround(py0 + (vy - ylo) / (yhi - ylo) * (py1 - py0))));
  };
  for (int k = 0; k <= 5; ++k) {  // y grid with labels
    const double v = ylo + k * (yhi - ylo) / 5;
    const int py = toPx(xlo, v).y;
    cv::line(img, {px0, py}, {px1, py}, kGrid, 1);
    text(img, format(v), {8, py + 5});
  }
  for (size_t i = 0; i < values.size(); ++i) {  // a tick per swept value
    const int px = toPx(x[i], ylo).x;
    cv::line(img, {px, py1}, {px, py0}, kGrid, 1);
    text(img, values[i], {px - 4 * static_cast<int>(values[i].size()), py0 + 20});
  }
  cv::rectangle(img, cv::Point(px0, py1), cv::Point(px1, py0), kBlack, 1);
  text(img, title, {px0, 22}, 0.6);
  text(img, xLabel + (numeric ? "" : " (categories)"), {(px0 + px1) / 2 - 80, kHeight - 20}, 0.5);

  for (size_t s = 0; s < series.size(); ++s) {
    const cv::Scalar colour = seriesColour(s);
    for (size_t i = 0; i < values.size(); ++i) {
      if (!series[s].lo.empty() && std::isfinite(series[s].lo[i]))
        cv::line(img, toPx(x[i], series[s].lo[i]), toPx(x[i], series[s].hi[i]), colour, 1);
      if (!std::isfinite(series[s].y[i])) continue;
      cv::circle(img, toPx(x[i], series[s].y[i]), 4, colour, cv::FILLED, cv::LINE_AA);
      for (size_t j = i + 1; j < values.size(); ++j)
        if (std::isfinite(series[s].y[j])) {
          cv::line(img, toPx(x[i], series[s].y[i]), toPx(x[j], series[s].y[j]), colour, 2,
                   cv::LINE_AA);
          break;
        }
    }
    const int ly = kTop + 10 + 22 * static_cast<int>(s);
    cv::line(img, {px1 + 15, ly}, {px1 + 40, ly}, colour, 2, cv::LINE_AA);
    std::string label = series[s].label;
    if (label.size() > 30) label = label.substr(0, 28) + "..";
    text(img, label, {px1 + 46, ly + 5}, 0.4);
  }
  if (!cv::imwrite(path, img)) throw std::runtime_error("cannot write the plot '" + path + "'");
}

}  // namespace

std::vector<std::string> writeSweepPlots(const SweepSpec& spec,
                                         const std::vector<JobResult>& results) {
  std::vector<std::string> paths;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t k = 0; k < spec.keys.size(); ++k) {
    const SweptKey& key = spec.keys[k];
    // APE RMSE of the scored jobs, by the other keys' values, then by this key's value index.
    std::map<std::string, std::map<size_t, std::vector<double>>> byOthers;
    for (const auto& r : results) {
      if (!r.ok || !r.ape) continue;
      std::string others;
      for (size_t o = 0; o < spec.keys.size(); ++o)
        if (o != k)
          others += (others.empty() ? "" : ", ") + spec.keys[o].name() + "=" +
                    spec.keys[o].values[r.job->combination.value_index[o]];
      byOthers[others][r.job->combination.value_index[k]].push_back(r.ape->rmse);
    }
    if (byOthers.empty()) continue;
    std::vector<Series> series;
    for (const auto& [others, perValue] : byOthers) {
      Series s{others.empty() ? "median over rawlogs" : others,
               std::vector<double>(key.values.size(), nan),
               {},
               {}};
      for (const auto& [v, rmses] : perValue) s.y[v] = median(rmses);
      series.push_back(std::move(s));
    }
    if (series.size() > kMaxSeries) {  // too many lines to read: their median and range
      Series m{"median of " + std::to_string(series.size()) + " combinations",
               std::vector<double>(key.values.size(), nan),
               std::vector<double>(key.values.size(), nan),
               std::vector<double>(key.values.size(), nan)};
      for (size_t v = 0; v < key.values.size(); ++v) {
        std::vector<double> ys;
        for (const auto& s : series)
          if (std::isfinite(s.y[v])) ys.push_back(s.y[v]);
        if (ys.empty()) continue;
        m.y[v] = median(ys);
        m.lo[v] = *std::min_element(ys.begin(), ys.end());
        m.hi[v] = *std::max_element(ys.begin(), ys.end());
      }
      series = {m};
    }
    const std::string path = (fs::path(spec.out) / ("plot_" + key.name() + ".png")).string();
    draw(path,
         "APE RMSE (m) against " + key.name() + " (median over " +
             std::to_string(spec.rawlogs.size()) + " rawlog" +
             (spec.rawlogs.size() > 1 ? "s)" : ")"),
         key.name(), key.values, series);
    paths.push_back(path);
  }
  return paths;
}

}  // namespace dynslam::sweep
