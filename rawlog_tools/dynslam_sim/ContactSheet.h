#pragma once
// A picture of a simulated sequence: a few frames, each as colour | depth (colour-mapped) |
// instance labels, side by side, so a person sees at a glance what the scenario looks like.
#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace dynslam::rawlog_tools {

class ContactSheet {
 public:
  /// `rows` frames will be added; each panel is scaled to `panel_width` pixels wide.
  explicit ContactSheet(int panel_width = 320);

  /// rgb CV_8UC3, depth CV_32FC1 (m, 0 invalid), label CV_16UC1; `caption` goes on the colour.
  void addRow(const cv::Mat& rgb, const cv::Mat& depth, const cv::Mat& label, double max_depth,
              const std::string& caption);
  /// Throws std::runtime_error naming the file when it cannot be written.
  void save(const std::string& png) const;

 private:
  int panel_width_;
  std::vector<cv::Mat> rows_;
};

}  // namespace dynslam::rawlog_tools
