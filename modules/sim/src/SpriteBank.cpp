#include <dynslam/sim/SpriteBank.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace dynslam::sim {
namespace {

constexpr const char* kIndex = "bank.txt";
constexpr const char* kMagic = "# dynslam sprite bank v1";

std::string pngName(size_t sequence, size_t frame) {
  char name[64];
  std::snprintf(name, sizeof name, "s%03zu/f%03zu.png", sequence, frame);
  return name;
}

/// One frame's line of bank.txt, parsed; throws naming the file and line.
struct IndexLine {
  size_t sequence = 0, frame = 0;
  SpriteFrame sprite;
};

IndexLine parseLine(const std::string& text, const std::string& where) {
  std::istringstream in(text);
  IndexLine l;
  in >> l.sequence >> l.frame >> l.sprite.video_frame >> l.sprite.crop_origin.x >>
      l.sprite.crop_origin.y >> l.sprite.foot.x >> l.sprite.foot.y >> l.sprite.height_px >>
      l.sprite.walked_heights;
  std::string rest;
  if (in.fail() || (in >> rest))
    throw std::runtime_error(where +
                             ": expected 'sequence frame video_frame crop_x crop_y foot_x "
                             "foot_y height_px walked_heights', got '" +
                             text + "'");
  return l;
}

}  // namespace

cv::Point2f footPointOfMask(const cv::Mat& mask) {
  const cv::Rect r = cv::boundingRect(mask);
  if (r.empty()) return {0, 0};
  const int bottom = r.y + r.height - 1;
  const int rows = std::max(1, int(std::lround(0.03 * r.height)));
  double sum = 0;
  int n = 0;
  for (int y = bottom - rows + 1; y <= bottom; ++y)
    for (int x = r.x; x < r.x + r.width; ++x)
      if (mask.at<uchar>(y, x)) sum += x, ++n;
  return {float(sum / n), float(bottom)};
}

size_t SpriteBank::frameCount() const {
  size_t n = 0;
  for (const auto& s : sequences) n += s.frames.size();
  return n;
}

cv::Point2f SpriteSequence::footVelocity() const {
  if (frames.size() < 2) return {0, 0};
  const auto inVideo = [](const SpriteFrame& f) { return cv::Point2f(f.crop_origin) + f.foot; };
  return (inVideo(frames.back()) - inVideo(frames.front())) / float(frames.size() - 1);
}

void writeSpriteBank(const SpriteBank& bank, const std::string& dir) {
  fs::create_directories(dir);
  std::ostringstream index;
  index << kMagic << "\n# source " << bank.source
        << "\n# sequence frame video_frame crop_x crop_y foot_x foot_y height_px walked_heights\n";
  for (size_t s = 0; s < bank.sequences.size(); ++s) {
    fs::create_directories((fs::path(dir) / pngName(s, 0)).parent_path());
    const auto& frames = bank.sequences[s].frames;
    for (size_t f = 0; f < frames.size(); ++f) {
      const SpriteFrame& sp = frames[f];
      const std::string png = (fs::path(dir) / pngName(s, f)).string();
      if (sp.bgra.type() != CV_8UC4 || !cv::imwrite(png, sp.bgra))
        throw std::runtime_error(png + ": cannot write the sprite");
      char line[160];
      std::snprintf(line, sizeof line, "%zu %zu %d %d %d %.2f %.2f %.1f %.4f\n", s, f,
                    sp.video_frame, sp.crop_origin.x, sp.crop_origin.y, sp.foot.x, sp.foot.y,
                    sp.height_px, sp.walked_heights);
      index << line;
    }
  }
  const std::string path = (fs::path(dir) / kIndex).string();
  std::ofstream out(path, std::ios::trunc);
  out << index.str();
  if (!out.flush()) throw std::runtime_error(path + ": cannot write the sprite bank's index");
}

SpriteBank readSpriteBank(const std::string& dir) {
  const std::string path = (fs::path(dir) / kIndex).string();
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error("sprite bank '" + dir + "': no " + kIndex +
                             " (make one with dynslam-sprites --video FILE --out " + dir + ")");
  SpriteBank bank;
  std::string text;
  size_t lineNo = 0;
  if (!std::getline(in, text) || text != kMagic)
    throw std::runtime_error(path + " line 1: not a sprite bank (expected '" + kMagic + "')");
  ++lineNo;
  while (std::getline(in, text)) {
    ++lineNo;
    if (text.rfind("# source ", 0) == 0) bank.source = text.substr(9);
    if (text.empty() || text[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(lineNo);
    IndexLine l = parseLine(text, where);
    if (l.sequence > bank.sequences.size() ||
        (l.sequence == bank.sequences.size() && l.frame != 0) ||
        (l.sequence < bank.sequences.size() && (l.sequence + 1 != bank.sequences.size() ||
                                                l.frame != bank.sequences.back().frames.size())))
      throw std::runtime_error(where + ": sequence " + std::to_string(l.sequence) + " frame " +
                               std::to_string(l.frame) + " is out of order");
    if (l.sequence == bank.sequences.size()) bank.sequences.emplace_back();
    const std::string png = (fs::path(dir) / pngName(l.sequence, l.frame)).string();
    l.sprite.bgra = cv::imread(png, cv::IMREAD_UNCHANGED);
    if (l.sprite.bgra.empty() || l.sprite.bgra.type() != CV_8UC4)
      throw std::runtime_error(png + " (" + where + "): missing or not a BGRA PNG");
    bank.sequences.back().frames.push_back(std::move(l.sprite));
  }
  if (bank.sequences.empty()) throw std::runtime_error(path + ": holds no sprite");
  return bank;
}

}  // namespace dynslam::sim
