#pragma once
// The pieces of a YOLO-family detector that do not need the network: letterboxing the image into
// the network input and decoding the three output layouts into scored boxes. Kept apart from the
// network so the decoders can be tested on synthetic tensors (no YOLOv5/v8 model is shipped).
//
// Layouts (80 COCO classes; N anchors or proposals):
//  - yolox:  1 x N x 85, per anchor (x, y, w, h, objectness, 80 class scores), sigmoids applied;
//            grid-relative: centre = (x + gx) * stride, size = exp(w) * stride, over the grids of
//            strides 8, 16 and 32 of the input, row by row (N = 3549 at 416 x 416, 2730 at
//            416 x 320, 2100 at 320 x 320); score = obj * cls.
//  - yolov5: 1 x N x 85, (cx, cy, w, h) in input pixels, objectness, class scores;
//            score = obj * cls.
//  - yolov8: 1 x 84 x N (transposed), (cx, cy, w, h) in input pixels, class scores; no
//            objectness: score = cls.
// The number of classes follows from the tensor's shape.
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include <string>
#include <vector>

namespace dynslam::detection {

enum class YoloLayout { YoloX, YoloV5, YoloV8 };

/// Resizing an image, aspect kept, into the top-left of the network input padded with grey 114.
struct Letterbox {
  double scale = 1;  ///< input pixels per image pixel

  /// The padded CV_8UC3 network input; sets `scale`. The image's longer side becomes
  /// `input_size`. `trim`: the input's other side is the shorter one's length rounded up to a
  /// multiple of 32 (the coarsest stride) rather than `input_size`, so a 640 x 480 image at 416
  /// becomes 416 x 320, not 416 x 416: the network sees the same pixels without the rows of
  /// grey padding (a quarter of its work), as "rectangular inference" in YOLOv5.
  cv::Mat apply(const cv::Mat& bgr, int input_size, bool trim = false);
  /// A box in input pixels back in image pixels.
  cv::Rect2f toImage(const cv::Rect2f& input_box) const;
};

struct YoloCandidate {
  cv::Rect2f box;    ///< input pixels, (x, y, width, height)
  int class_id = 0;  ///< the best-scoring class
  float score = 0;
};

/// Every anchor or proposal whose best class scores at least `min_score`. `output` is the
/// network's output blob (3 dims, batch 1, CV_32F) for an input of `input` pixels. Throws
/// std::invalid_argument when its shape does not fit the layout (for yolox: does not match the
/// grids of `input`).
std::vector<YoloCandidate> decodeYoloOutput(const cv::Mat& output, YoloLayout layout,
                                            cv::Size input, float min_score);

}  // namespace dynslam::detection
