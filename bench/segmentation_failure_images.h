#pragma once
// bench-segmentation's --dump: keeps the worst-scoring masks of a run and writes each as a PNG
// (the box and a margin around it: colour with the mask over it, green where it is the person,
// red where it is not, blue where the person was missed | the depth, 0-6 m, with the person's
// outline), to look at why a mask fails.
#include <dynslam/core/Perception.h>
#include <dynslam/sim/SimFrame.h>

#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

class FailureDumper {
 public:
  /// `dir` empty: does nothing.
  FailureDumper(std::string dir, size_t maxImages) : dir_(std::move(dir)), max_(maxImages) {}

  /// Starts the names of the images kept from now on (the scenario's name).
  void setPrefix(std::string prefix) { prefix_ = std::move(prefix); }
  const std::string& prefix() const { return prefix_; }

  /// One scored mask: `iou` (< 0 when not scored) and the d_t error in %.
  void consider(const dynslam::sim::SimFrame& frame, const dynslam::sim::ObjectTruth& truth,
                const dynslam::core::ObjectMask& mask, double iou, double depthErrPercent);

  /// Writes the kept images and prints their names.
  void write() const;

 private:
  struct Kept {
    double badness;
    std::string name;
    cv::Mat image;
  };
  std::string dir_, prefix_;
  size_t max_;
  std::vector<Kept> kept_;
};
