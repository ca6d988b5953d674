#include "SpriteContactSheet.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace {

constexpr int kRowHeight = 120, kCellWidth = 90, kCaptionWidth = 150, kPerRow = 8;

/// The sprite scaled to the row's height, blended onto grey by its alpha.
cv::Mat onGrey(const cv::Mat& bgra) {
  const double scale = double(kRowHeight - 8) / bgra.rows;
  cv::Mat small;
  cv::resize(bgra, small, cv::Size(), scale, scale, cv::INTER_AREA);
  cv::Mat out(small.size(), CV_8UC3, cv::Scalar(128, 128, 128));
  for (int y = 0; y < small.rows; ++y)
    for (int x = 0; x < small.cols; ++x) {
      const cv::Vec4b p = small.at<cv::Vec4b>(y, x);
      const double a = p[3] / 255.0;
      for (int c = 0; c < 3; ++c)
        out.at<cv::Vec3b>(y, x)[c] = cv::saturate_cast<uchar>(a * p[c] + (1 - a) * 128);
    }
  return out;
}

}  // namespace

void writeSpriteContactSheet(const dynslam::sim::SpriteBank& bank, const std::string& png) {
  const int rows = int(bank.sequences.size());
  cv::Mat sheet(std::max(1, rows) * kRowHeight, kCaptionWidth + kPerRow * kCellWidth, CV_8UC3,
                cv::Scalar(128, 128, 128));
  for (int r = 0; r < rows; ++r) {
    const auto& frames = bank.sequences[size_t(r)].frames;
    const double cycles = frames.back().walked_heights / 0.8;
    char caption[64];
    std::snprintf(caption, sizeof caption, "s%03d: %zu f", r, frames.size());
    cv::putText(sheet, caption, {6, r * kRowHeight + 50}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    std::snprintf(caption, sizeof caption, "%.1f cycles", cycles);
    cv::putText(sheet, caption, {6, r * kRowHeight + 72}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    const int shown = std::min<int>(kPerRow, int(frames.size()));
    for (int k = 0; k < shown; ++k) {
      const size_t i = shown == 1 ? 0 : size_t(k) * (frames.size() - 1) / size_t(shown - 1);
      cv::Mat cell = onGrey(frames[i].bgra);
      const int width = std::min(cell.cols, kCellWidth - 4);
      cell(cv::Rect(0, 0, width, cell.rows))
          .copyTo(sheet(
              cv::Rect(kCaptionWidth + k * kCellWidth, r * kRowHeight + 4, width, cell.rows)));
    }
  }
  if (!cv::imwrite(png, sheet))
    throw std::runtime_error("--contact-sheet " + png + ": cannot write the picture");
}
