// Letterboxing and the three output decoders on synthetic tensors whose boxes are known (no
// YOLOv5/v8 model is available here; the YOLOX decoder is also exercised by the model tests).
#include <dynslam/detection/YoloOutput.h>

#include <gtest/gtest.h>

#include <cmath>

namespace det = dynslam::detection;

namespace {

cv::Mat blob(int a, int b) {
  const int sizes[] = {1, a, b};
  return cv::Mat(3, sizes, CV_32F, cv::Scalar(0));
}

void expectBox(const cv::Rect2f& box, float x, float y, float w, float h) {
  EXPECT_NEAR(box.x, x, 1e-3);
  EXPECT_NEAR(box.y, y, 1e-3);
  EXPECT_NEAR(box.width, w, 1e-3);
  EXPECT_NEAR(box.height, h, 1e-3);
}

}  // namespace

TEST(YoloOutput, LetterboxPutsTheImageTopLeftOnGreyAndMapsBoxesBack) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(10, 20, 30));
  det::Letterbox lb;
  const cv::Mat input = lb.apply(image, 416);
  ASSERT_EQ(input.size(), cv::Size(416, 416));
  EXPECT_DOUBLE_EQ(lb.scale, 0.65);
  EXPECT_EQ(input.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(input.at<cv::Vec3b>(311, 415), cv::Vec3b(10, 20, 30));  // last image row: 312 * 0.65
  EXPECT_EQ(input.at<cv::Vec3b>(312, 0), cv::Vec3b(114, 114, 114));
  expectBox(lb.toImage({65, 13, 130, 26}), 100, 20, 200, 40);
}

TEST(YoloOutput, TrimmedLetterboxKeepsOnlyThePaddingUpToTheCoarsestStride) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(10, 20, 30));
  det::Letterbox lb;
  const cv::Mat input = lb.apply(image, 416, /*trim=*/true);
  ASSERT_EQ(input.size(), cv::Size(416, 320)) << "312 image rows, rounded up to 32";
  EXPECT_DOUBLE_EQ(lb.scale, 0.65) << "the same scale as the square input";
  EXPECT_EQ(input.at<cv::Vec3b>(311, 415), cv::Vec3b(10, 20, 30));
  EXPECT_EQ(input.at<cv::Vec3b>(312, 0), cv::Vec3b(114, 114, 114));
  const cv::Mat portrait(640, 480, CV_8UC3, cv::Scalar(1, 2, 3));
  EXPECT_EQ(lb.apply(portrait, 416, true).size(), cv::Size(320, 416));
  const cv::Mat exact(320, 416, CV_8UC3, cv::Scalar(1, 2, 3));
  EXPECT_EQ(lb.apply(exact, 416, true).size(), cv::Size(416, 320)) << "no padding needed";
}

TEST(YoloOutput, YoloXDecodesGridCellsOfEachStride) {
  const int input = 320;  // grids 40x40, 20x20, 10x10: 2100 anchors
  cv::Mat out = blob(2100, 85);
  // Stride 8, cell (gx 3, gy 5): row 5 * 40 + 3. Person (class 0) at 0.9 x 0.8.
  float* a = out.ptr<float>() + (5 * 40 + 3) * 85;
  a[0] = 0.5f, a[1] = 0.25f, a[2] = std::log(4.f), a[3] = std::log(2.f), a[4] = 0.9f;
  a[5 + 0] = 0.8f;
  a[5 + 2] = 0.1f;
  // Stride 32, cell (gx 1, gy 2): row 1600 + 400 + 2 * 10 + 1. Car (class 2) at 0.5 x 0.9.
  float* b = out.ptr<float>() + (1600 + 400 + 21) * 85;
  b[0] = 0, b[1] = 0, b[2] = 0, b[3] = 0, b[4] = 0.5f, b[5 + 2] = 0.9f;
  // Below the threshold: objectness 0.9 but class score 0.2 -> 0.18.
  out.ptr<float>()[85 * 10 + 4] = 0.9f, out.ptr<float>()[85 * 10 + 5] = 0.2f;

  const auto found =
      det::decodeYoloOutput(out, det::YoloLayout::YoloX, cv::Size(input, input), 0.3f);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].class_id, 0);
  EXPECT_NEAR(found[0].score, 0.72f, 1e-6);
  // centre ((0.5 + 3) * 8, (0.25 + 5) * 8) = (28, 42), size (32, 16)
  expectBox(found[0].box, 12, 34, 32, 16);
  EXPECT_EQ(found[1].class_id, 2);
  EXPECT_NEAR(found[1].score, 0.45f, 1e-6);
  // centre (1 * 32, 2 * 32), size (32, 32)
  expectBox(found[1].box, 16, 48, 32, 32);
}

TEST(YoloOutput, YoloXReadsTheGridsOfAWideInputRowByRow) {
  // 96 x 64: grids 12x8, 6x4 and 3x2, 126 anchors. Stride 8, cell (gx 5, gy 3): row 3 * 12 + 5;
  // stride 16, cell (gx 4, gy 1): row 96 + 1 * 6 + 4.
  cv::Mat out = blob(126, 85);
  float* a = out.ptr<float>() + (3 * 12 + 5) * 85;
  a[4] = 0.9f, a[5] = 0.9f;
  float* b = out.ptr<float>() + (96 + 6 + 4) * 85;
  b[4] = 0.8f, b[5 + 2] = 0.9f;
  const auto found = det::decodeYoloOutput(out, det::YoloLayout::YoloX, cv::Size(96, 64), 0.3f);
  ASSERT_EQ(found.size(), 2u);
  expectBox(found[0].box, 5 * 8 - 4, 3 * 8 - 4, 8, 8);  // centre (40, 24), size exp(0) * 8
  expectBox(found[1].box, 4 * 16 - 8, 1 * 16 - 8, 16, 16);
}

TEST(YoloOutput, YoloXRejectsAnOutputThatDoesNotFitTheInputSize) {
  try {
    det::decodeYoloOutput(blob(3549, 85), det::YoloLayout::YoloX, cv::Size(320, 320), 0.3f);
    FAIL() << "no error for a 416 grid read as 320";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("1x3549x85"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1x2100x"), std::string::npos) << e.what();
  }
}

TEST(YoloOutput, YoloV5DecodesPixelBoxesTimesObjectness) {
  cv::Mat out = blob(3, 85);
  float* p = out.ptr<float>() + 85;                                              // second proposal
  p[0] = 100, p[1] = 200, p[2] = 40, p[3] = 120, p[4] = 0.8f, p[5 + 7] = 0.75f;  // truck
  out.ptr<float>()[2 * 85 + 4] = 0.2f, out.ptr<float>()[2 * 85 + 5] = 1.f;       // 0.2: too low
  const auto found = det::decodeYoloOutput(out, det::YoloLayout::YoloV5, cv::Size(640, 640), 0.25f);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].class_id, 7);
  EXPECT_NEAR(found[0].score, 0.6f, 1e-6);
  expectBox(found[0].box, 80, 140, 40, 120);
}

TEST(YoloOutput, YoloV8DecodesTheTransposedLayoutWithoutObjectness) {
  const int n = 5;
  cv::Mat out = blob(84, n);
  float* base = out.ptr<float>();
  const auto set = [&](int channel, int proposal, float v) { base[channel * n + proposal] = v; };
  set(0, 3, 300), set(1, 3, 100), set(2, 3, 60), set(3, 3, 20), set(4 + 2, 3, 0.7f);  // car
  set(4 + 0, 3, 0.4f);                                                                // person
  set(4 + 0, 1, 0.1f);                                                                // too low
  const auto found = det::decodeYoloOutput(out, det::YoloLayout::YoloV8, cv::Size(640, 640), 0.25f);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].class_id, 2);
  EXPECT_NEAR(found[0].score, 0.7f, 1e-6);
  expectBox(found[0].box, 270, 90, 60, 20);
}

TEST(YoloOutput, RejectsBlobsOfTheWrongShape) {
  const cv::Mat flat(10, 85, CV_32F, cv::Scalar(0));
  EXPECT_THROW(det::decodeYoloOutput(flat, det::YoloLayout::YoloV5, cv::Size(640, 640), 0.3f),
               std::invalid_argument);
  EXPECT_THROW(
      det::decodeYoloOutput(blob(10, 4), det::YoloLayout::YoloV5, cv::Size(640, 640), 0.3f),
      std::invalid_argument);
}
