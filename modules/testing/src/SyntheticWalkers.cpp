#include <dynslam/testing/SyntheticWalkers.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dynslam::testing {
namespace {

/// The figure's silhouette: head, torso and two legs swinging with the distance walked.
cv::Mat silhouette(cv::Size size, cv::Point2f foot, int height, double walked) {
  cv::Mat mask(size, CV_8UC1, cv::Scalar(0));
  const double h = height, swing = 0.12 * h * std::sin(2 * M_PI * walked / (0.8 * h));
  const cv::Point2f hip(foot.x, foot.y - 0.47f * float(h));
  const auto leg = [&](double dx) {
    const std::vector<cv::Point> quad{cv::Point(int(hip.x - 0.06 * h), int(hip.y)),
                                      cv::Point(int(hip.x + 0.06 * h), int(hip.y)),
                                      cv::Point(int(foot.x + dx + 0.04 * h), int(foot.y)),
                                      cv::Point(int(foot.x + dx - 0.04 * h), int(foot.y))};
    cv::fillConvexPoly(mask, quad, cv::Scalar(255), cv::LINE_8);
  };
  leg(swing);
  leg(-swing);
  cv::ellipse(mask, cv::Point(int(foot.x), int(foot.y - 0.66 * h)),
              cv::Size(int(0.13 * h), int(0.22 * h)), 0, 0, 360, cv::Scalar(255), cv::FILLED);
  cv::circle(mask, cv::Point(int(foot.x), int(foot.y - 0.93 * h)), int(0.07 * h), cv::Scalar(255),
             cv::FILLED);
  return mask;
}

}  // namespace

cv::Mat SyntheticWalkerScene::background() const {
  cv::Mat out(size, CV_8UC3);
  cv::RNG rng(7);
  for (int y = 0; y < size.height; y += 8)
    for (int x = 0; x < size.width; x += 8) {
      const int v = rng.uniform(80, 160);
      const cv::Scalar grey(v + rng.uniform(-6, 6), v + rng.uniform(-6, 6), v + rng.uniform(-6, 6));
      cv::rectangle(out, cv::Rect(x, y, 8, 8), grey, cv::FILLED);
    }
  return out;
}

cv::Mat SyntheticWalkerScene::frame(int i, std::vector<cv::Mat>* masks) const {
  cv::Mat image = background();
  std::vector<size_t> order(walkers.size());
  std::iota(order.begin(), order.end(), 0);
  const double s = frames > 1 ? double(i) / (frames - 1) : 0.0;
  const auto footOf = [&](size_t w) {
    return walkers[w].foot_start + (walkers[w].foot_end - walkers[w].foot_start) * s;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return footOf(a).y < footOf(b).y; });
  if (masks) {
    masks->clear();
    for (size_t w = 0; w < walkers.size(); ++w)
      masks->push_back(cv::Mat(size, CV_8UC1, cv::Scalar(0)));
  }
  for (size_t w : order) {
    const SyntheticWalker& walker = walkers[w];
    const double walked = cv::norm(footOf(w) - walker.foot_start);
    const cv::Mat mask = silhouette(size, footOf(w), walker.height_px, walked);
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x)
        if (mask.at<uchar>(y, x)) {
          const cv::Scalar& c = ((y / 6) % 2) ? walker.colour_a : walker.colour_b;
          image.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(c[0]), uchar(c[1]), uchar(c[2]));
        }
    if (masks) {
      for (auto& m : *masks) m.setTo(0, mask);  // nearer walkers hide the farther ones
      (*masks)[w].setTo(255, mask);
    }
  }
  cv::Mat noise(size, CV_16SC3);
  cv::RNG rng(uint64_t(1000 + i));
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  cv::Mat noisy;
  image.convertTo(noisy, CV_16SC3);
  noisy += noise;
  noisy.convertTo(image, CV_8UC3);
  return image;
}

}  // namespace dynslam::testing
