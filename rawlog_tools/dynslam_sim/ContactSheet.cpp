#include "ContactSheet.h"

#include <dynslam/viz/IdColours.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace dynslam::rawlog_tools {

ContactSheet::ContactSheet(int panel_width) : panel_width_(panel_width) {}

void ContactSheet::addRow(const cv::Mat& rgb, const cv::Mat& depth, const cv::Mat& label,
                          double max_depth, const std::string& caption) {
  cv::Mat depth8, depthColour, invalid = depth <= 0;
  depth.convertTo(depth8, CV_8UC1, 255.0 / max_depth);
  cv::applyColorMap(depth8, depthColour, cv::COLORMAP_TURBO);
  depthColour.setTo(cv::Scalar(0, 0, 0), invalid);
  cv::Mat labelColours(label.size(), CV_8UC3);
  for (int v = 0; v < label.rows; ++v)
    for (int u = 0; u < label.cols; ++u) {
      const cv::Scalar c = viz::colourForId(label.at<uint16_t>(v, u));
      labelColours.at<cv::Vec3b>(v, u) =
          cv::Vec3b(static_cast<uchar>(c[0]), static_cast<uchar>(c[1]), static_cast<uchar>(c[2]));
    }

  const double scale = panel_width_ / static_cast<double>(rgb.cols);
  const cv::Size size(panel_width_, static_cast<int>(rgb.rows * scale + 0.5));
  std::vector<cv::Mat> panels(3);
  cv::resize(rgb, panels[0], size, 0, 0, cv::INTER_AREA);
  cv::resize(depthColour, panels[1], size, 0, 0, cv::INTER_NEAREST);
  cv::resize(labelColours, panels[2], size, 0, 0, cv::INTER_NEAREST);
  cv::putText(panels[0], caption, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 3);
  cv::putText(panels[0], caption, {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {255, 255, 255}, 1);
  cv::Mat row;
  cv::hconcat(panels, row);
  rows_.push_back(row);
}

void ContactSheet::save(const std::string& png) const {
  if (rows_.empty()) throw std::runtime_error("contact sheet '" + png + "' has no frames");
  cv::Mat sheet;
  cv::vconcat(rows_, sheet);
  if (!cv::imwrite(png, sheet)) throw std::runtime_error("cannot write '" + png + "'");
}

}  // namespace dynslam::rawlog_tools
