#include <dynslam/sim/SpriteExtractor.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace dynslam::sim {
namespace {

enum class Verdict { Usable, CutByBorder, TwoPeople, TooSmall };

/// One followed person in one frame.
struct Sighting {
  int frame = 0;
  cv::Rect box;
  cv::Point crop_origin;
  cv::Mat bgra;  ///< the colour crop with the blob as alpha
  Verdict verdict = Verdict::Usable;
};

struct FollowedPerson {
  cv::Rect last_box;
  int last_frame = 0;
  std::vector<Sighting> sightings;
};

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double inter = (a & b).area();
  return inter > 0 ? inter / double(a.area() + b.area() - inter) : 0.0;
}

/// The median of `size` (a box's height or width) over sightings [first, last).
template <typename Size>
double medianOf(const std::vector<Sighting>& s, size_t first, size_t last, Size size) {
  std::vector<int> v;
  for (size_t i = first; i < last; ++i) v.push_back(size(s[i].box));
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// Each frame's walked distance since the first, in heights: the path of the foot smoothed
/// over up to five frames (the mask's bottom row jitters by a pixel or two as the legs swing).
void setWalkedDistance(SpriteSequence& seq, double height) {
  const size_t n = seq.frames.size();
  std::vector<cv::Point2f> foot(n), smooth(n);
  for (size_t i = 0; i < n; ++i)
    foot[i] = cv::Point2f(seq.frames[i].crop_origin) + seq.frames[i].foot;
  for (size_t i = 0; i < n; ++i) {
    const size_t r = std::min({size_t(2), i, n - 1 - i});  // symmetric: the ends stay put
    const size_t a = i - r, b = i + r;
    cv::Point2f sum(0, 0);
    for (size_t k = a; k <= b; ++k) sum += foot[k];
    smooth[i] = sum / float(b - a + 1);
  }
  double walked = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0) walked += cv::norm(smooth[i] - smooth[i - 1]);
    seq.frames[i].walked_heights = walked / height;
  }
}

}  // namespace

struct SpriteExtractor::Impl {
  cv::Mat background;
  SpriteExtractionOptions o;
  SpriteExtractionReport report;
  std::vector<FollowedPerson> active, ended;
  int frame = 0;

  Sighting sight(const cv::Mat& bgr, const ForegroundBlob& blob, bool shared) const;
  void follow(const cv::Mat& bgr, const std::vector<ForegroundBlob>& blobs);
  void endMissing();
  void cutStretches(const FollowedPerson& p, std::vector<SpriteSequence>& out);
  void keepStretch(const std::vector<Sighting>& s, size_t first, size_t last,
                   std::vector<SpriteSequence>& out);
};

/// The blob as a sighting: its colour crop (2 px round the box) with the blob as alpha, and
/// whether the frame can be used.
Sighting SpriteExtractor::Impl::sight(const cv::Mat& bgr, const ForegroundBlob& blob,
                                      bool shared) const {
  Sighting s;
  s.frame = frame;
  s.box = blob.box;
  const cv::Rect crop =
      (blob.box - cv::Point(2, 2) + cv::Size(4, 4)) & cv::Rect(0, 0, bgr.cols, bgr.rows);
  s.crop_origin = crop.tl();
  cv::Mat alpha(crop.size(), CV_8UC1, cv::Scalar(0));
  blob.mask.copyTo(alpha(blob.box - crop.tl()));
  cv::merge(std::vector<cv::Mat>{bgr(crop), alpha}, s.bgra);
  const int m = o.border_margin_px;
  if (blob.box.x < m || blob.box.y < m || blob.box.br().x > bgr.cols - m ||
      blob.box.br().y > bgr.rows - m)
    s.verdict = Verdict::CutByBorder;
  else if (shared || blob.box.width > 0.8 * blob.box.height)
    s.verdict = Verdict::TwoPeople;
  else if (blob.box.height < o.min_height_px)
    s.verdict = Verdict::TooSmall;
  return s;
}

/// Links this frame's blobs to the people followed so far, largest box overlap first, one to
/// one; a blob two people overlap holds both (neither frame is used); a blob nobody overlaps
/// starts a new person.
void SpriteExtractor::Impl::follow(const cv::Mat& bgr, const std::vector<ForegroundBlob>& blobs) {
  std::vector<std::tuple<double, size_t, size_t>> pairs;  // (-iou, person, blob)
  std::vector<int> claims(blobs.size(), 0);
  for (size_t p = 0; p < active.size(); ++p)
    for (size_t b = 0; b < blobs.size(); ++b)
      if (const double v = iou(active[p].last_box, blobs[b].box); v >= 0.2) {
        pairs.emplace_back(-v, p, b);
        ++claims[b];
      }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> personOf(blobs.size(), -1);
  std::vector<bool> seen(active.size(), false);
  for (const auto& [negIou, p, b] : pairs) {
    const bool shared = claims[b] > 1;
    if (seen[p] || (personOf[b] >= 0 && !shared)) continue;
    seen[p] = true;
    if (personOf[b] < 0) personOf[b] = int(p);
    active[p].sightings.push_back(sight(bgr, blobs[b], shared));
    active[p].last_box = blobs[b].box;
    active[p].last_frame = frame;
  }
  for (size_t b = 0; b < blobs.size(); ++b)
    if (personOf[b] < 0 && claims[b] == 0) {
      FollowedPerson person;
      person.sightings.push_back(sight(bgr, blobs[b], false));
      person.last_box = blobs[b].box;
      person.last_frame = frame;
      active.push_back(std::move(person));
      ++report.followed;
    }
}

void SpriteExtractor::Impl::endMissing() {
  for (auto it = active.begin(); it != active.end();)
    if (frame - it->last_frame > o.max_missed_frames) {
      ended.push_back(std::move(*it));
      it = active.erase(it);
    } else {
      ++it;
    }
}

/// A person's unbroken stretches of usable frames (consecutive video frames).
void SpriteExtractor::Impl::cutStretches(const FollowedPerson& p,
                                         std::vector<SpriteSequence>& out) {
  const auto& s = p.sightings;
  size_t first = 0;
  for (size_t i = 0; i <= s.size(); ++i) {
    const bool breaks = i == s.size() || s[i].verdict != Verdict::Usable ||
                        (i > first && s[i].frame != s[i - 1].frame + 1);
    if (i < s.size()) {
      report.cut_by_border += s[i].verdict == Verdict::CutByBorder;
      report.two_people += s[i].verdict == Verdict::TwoPeople;
      report.too_small += s[i].verdict == Verdict::TooSmall;
    }
    if (!breaks) continue;
    if (i > first) keepStretch(s, first, i, out);
    first = (i < s.size() && s[i].verdict != Verdict::Usable) ? i + 1 : i;
  }
}

/// Keeps a stretch that walks at least the minimum number of gait cycles and is one person
/// wide; frames far taller, shorter or wider than the stretch's median (someone passing close
/// behind, a part lost) end it there.
void SpriteExtractor::Impl::keepStretch(const std::vector<Sighting>& s, size_t first, size_t last,
                                        std::vector<SpriteSequence>& out) {
  const double height = medianOf(s, first, last, [](const cv::Rect& r) { return r.height; });
  const double width = medianOf(s, first, last, [](const cv::Rect& r) { return r.width; });
  for (size_t i = first; i < last; ++i)
    if (std::abs(s[i].box.height - height) > 0.25 * height || s[i].box.width > 1.6 * width) {
      ++report.size_jumps;
      if (i > first) keepStretch(s, first, i, out);
      if (i + 1 < last) keepStretch(s, i + 1, last, out);
      return;
    }
  if (width > o.max_median_width * height) {
    ++report.pairs;
    return;
  }
  SpriteSequence seq;
  for (size_t i = first; i < last; ++i) {
    SpriteFrame f;
    f.video_frame = s[i].frame;
    f.crop_origin = s[i].crop_origin;
    f.bgra = s[i].bgra;
    cv::Mat alpha;
    cv::extractChannel(s[i].bgra, alpha, 3);
    f.foot = footPointOfMask(alpha);
    f.height_px = s[i].box.height;
    seq.frames.push_back(std::move(f));
  }
  setWalkedDistance(seq, height);
  if (seq.frames.size() < 4 ||
      seq.frames.back().walked_heights < o.gait_cycle_heights * o.min_gait_cycles) {
    ++report.short_stretches;
    return;
  }
  out.push_back(std::move(seq));
}

SpriteExtractor::SpriteExtractor(cv::Mat background, SpriteExtractionOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->background = std::move(background);
  impl_->o = options;
}

SpriteExtractor::~SpriteExtractor() = default;

void SpriteExtractor::add(const cv::Mat& bgr) {
  const cv::Mat mask = foregroundMask(bgr, impl_->background, impl_->o.foreground);
  // Blobs down to half the minimum height keep a person followed while partly hidden.
  impl_->follow(bgr, foregroundBlobs(mask, std::max(1, impl_->o.min_height_px / 2)));
  impl_->endMissing();
  ++impl_->frame;
  ++impl_->report.frames;
}

SpriteBank SpriteExtractor::finish(const std::string& source) {
  Impl& m = *impl_;
  for (auto& p : m.active) m.ended.push_back(std::move(p));
  m.active.clear();
  SpriteBank bank;
  bank.source = source;
  for (const auto& p : m.ended) {
    const size_t before = bank.sequences.size();
    m.cutStretches(p, bank.sequences);
    m.report.people += bank.sequences.size() > before;
  }
  std::stable_sort(bank.sequences.begin(), bank.sequences.end(),
                   [](const SpriteSequence& a, const SpriteSequence& b) {
                     return std::make_pair(a.frames[0].video_frame, a.frames[0].crop_origin.x) <
                            std::make_pair(b.frames[0].video_frame, b.frames[0].crop_origin.x);
                   });
  m.report.sequences = bank.sequences.size();
  m.report.sprite_frames = bank.frameCount();
  m.ended.clear();
  return bank;
}

const SpriteExtractionReport& SpriteExtractor::report() const { return impl_->report; }

}  // namespace dynslam::sim
