#include "dynslam/frontend/GridCornerDetector.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynslam::frontend {
namespace {

struct Candidate {
  cv::Point2f pixel;
  float quality;  // min eigenvalue
};

/// The grid cell rectangles, clipped to the image minus its border.
std::vector<cv::Rect> gridCells(cv::Size size, const GridCornerParams& p) {
  const cv::Rect inner(p.border_px, p.border_px, size.width - 2 * p.border_px,
                       size.height - 2 * p.border_px);
  std::vector<cv::Rect> cells;
  for (int r = 0; r < p.grid_rows; ++r)
    for (int c = 0; c < p.grid_cols; ++c) {
      const int x0 = c * size.width / p.grid_cols, x1 = (c + 1) * size.width / p.grid_cols;
      const int y0 = r * size.height / p.grid_rows, y1 = (r + 1) * size.height / p.grid_rows;
      cells.push_back(cv::Rect(x0, y0, x1 - x0, y1 - y0) & inner);
    }
  return cells;
}

int cellOf(const cv::Point2f& p, cv::Size size, const GridCornerParams& params) {
  const int col = std::clamp(int(p.x * params.grid_cols / size.width), 0, params.grid_cols - 1);
  const int row = std::clamp(int(p.y * params.grid_rows / size.height), 0, params.grid_rows - 1);
  return row * params.grid_cols + col;
}

/// A cell's Shi-Tomasi corners (full-resolution `cell`) where `freeScored` allows, strongest
/// first, in full-resolution pixels. The filters read the pixels around the cell (a submatrix
/// keeps its parent's neighbours), so cells see no artificial border.
std::vector<Candidate> cellCorners(const cv::Mat& scored, const cv::Mat& freeScored,
                                   const cv::Rect& cell, int maxCorners,
                                   const GridCornerParams& p) {
  std::vector<Candidate> out;
  const int scale = 1 << p.level;
  const cv::Rect rect =
      cv::Rect(cell.x / scale, cell.y / scale, cell.width / scale, cell.height / scale) &
      cv::Rect(0, 0, scored.cols, scored.rows);
  if (rect.width <= 0 || rect.height <= 0 || cv::countNonZero(freeScored(rect)) == 0) return out;
  std::vector<cv::Point2f> corners;
  std::vector<float> quality;
  cv::goodFeaturesToTrack(scored(rect), corners, maxCorners, p.quality_level,
                          p.min_distance_px / scale, freeScored(rect), quality, p.block_size);
  for (size_t i = 0; i < corners.size(); ++i) {
    if (quality[i] < p.min_eigenvalue) continue;
    // Pixel centres: level pixel u covers full-resolution [scale u, scale (u + 1)).
    const cv::Point2f full((corners[i].x + float(rect.x) + 0.5f) * float(scale) - 0.5f,
                           (corners[i].y + float(rect.y) + 0.5f) * float(scale) - 0.5f);
    out.push_back({full, quality[i]});
  }
  return out;
}

}  // namespace

cv::Mat freeSpaceMask(cv::Size size, const std::vector<cv::Point2f>& occupied,
                      const GridCornerParams& params) {
  cv::Mat free(size, CV_8UC1, cv::Scalar(255));
  const int radius = int(std::ceil(params.min_distance_px));
  for (const auto& p : occupied)
    cv::circle(free, cv::Point(cvRound(p.x), cvRound(p.y)), radius, cv::Scalar(0), cv::FILLED);
  return free;
}

bool claimIfFree(cv::Mat& free, const cv::Point2f& p, const GridCornerParams& params) {
  const cv::Point pixel(cvRound(p.x), cvRound(p.y));
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= free.cols || pixel.y >= free.rows ||
      free.at<uint8_t>(pixel) == 0)
    return false;
  cv::circle(free, pixel, int(std::ceil(params.min_distance_px)), cv::Scalar(0), cv::FILLED);
  return true;
}

std::vector<cv::Point2f> detectGridCorners(
    const cv::Mat& scored, cv::Mat& free, const std::vector<cv::Point2f>& occupied, int wanted,
    const GridCornerParams& params, int* cellsComputed,
    const std::function<bool(const cv::Point2f&)>& rejected) {
  std::vector<cv::Point2f> taken;
  if (cellsComputed) *cellsComputed = 0;
  const cv::Size size = free.size();
  if (wanted <= 0 || size.width <= 2 * params.border_px || size.height <= 2 * params.border_px)
    return taken;
  cv::Mat freeScored = free;  // where candidates may be proposed, at the scored resolution
  if (scored.size() != size) cv::resize(free, freeScored, scored.size(), 0, 0, cv::INTER_NEAREST);
  const std::vector<cv::Rect> cells = gridCells(size, params);
  const size_t n = cells.size();
  std::vector<int> count(n, 0);
  for (const auto& p : occupied) ++count[size_t(cellOf(p, size, params))];
  std::vector<std::vector<Candidate>> bucket(n);
  std::vector<bool> computed(n, false);
  std::vector<size_t> head(n, 0);
  const auto hasMore = [&](size_t c) { return !computed[c] || head[c] < bucket[c].size(); };

  taken.reserve(size_t(wanted));
  std::vector<size_t> round;
  while (int(taken.size()) < wanted) {
    int level = std::numeric_limits<int>::max();
    for (size_t c = 0; c < n; ++c)
      if (hasMore(c)) level = std::min(level, count[c]);
    if (level == std::numeric_limits<int>::max()) break;  // no candidate left anywhere
    round.clear();
    for (size_t c = 0; c < n; ++c) {
      if (count[c] != level || !hasMore(c)) continue;
      if (!computed[c]) {  // the filling reached this cell: compute its corners now
        bucket[c] = cellCorners(scored, freeScored, cells[c], wanted, params);
        computed[c] = true;
        if (cellsComputed) ++*cellsComputed;
      }
      // Skip candidates that a corner taken since (in a neighbouring cell) crowds out, and the
      // rejected ones.
      const auto skipped = [&](const cv::Point2f& p) {
        return free.at<uint8_t>(cv::Point(cvRound(p.x), cvRound(p.y))) == 0 ||
               (rejected && rejected(p));
      };
      while (head[c] < bucket[c].size() && skipped(bucket[c][head[c]].pixel)) ++head[c];
      if (head[c] < bucket[c].size()) round.push_back(c);
    }
    if (round.empty()) continue;  // those cells turned out empty; the level moves on
    // Within a round, stronger candidates first: the cut at `wanted` drops the weakest.
    std::sort(round.begin(), round.end(), [&](size_t a, size_t b) {
      return bucket[a][head[a]].quality > bucket[b][head[b]].quality;
    });
    for (size_t c : round) {
      const cv::Point2f p = bucket[c][head[c]++].pixel;
      if (!claimIfFree(free, p, params)) continue;  // crowded out within this round
      taken.push_back(p);
      ++count[c];
      if (int(taken.size()) == wanted) break;
    }
  }
  return taken;
}

}  // namespace dynslam::frontend
