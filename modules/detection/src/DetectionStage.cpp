#include "dynslam/detection/DetectionStage.h"

#include "dynslam/detection/RealtimeDetector.h"

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>

namespace dynslam::detection {

DetectionStage::DetectionStage() = default;
DetectionStage::~DetectionStage() = default;

void DetectionStage::configure(const core::IniConfig& cfg, const std::string& section) {
  // The detector decides which keys the section may hold, so it is read before the strict load.
  try {
    options_.detector = core::readOneOf(cfg.ini(), section, "detector", options_.detector,
                                        DetectionOptions::kDetectors);
  } catch (const std::invalid_argument& e) {
    throw core::ConfigError(std::string(e.what()) + " in [" + section + "] of " + cfg.source());
  }
  core::loadOptionsStrict(options_, cfg, section);
  auto detector = makeDetector(cfg, section);
  if (options_.mode == "realtime")
    realtime_ = std::make_unique<RealtimeDetector>(std::move(detector));
  else
    detector_ = std::move(detector);
}

std::unique_ptr<Detector> DetectionStage::makeDetector(const core::IniConfig& cfg,
                                                       const std::string& section) const {
  const auto where = "[" + section + "] of " + cfg.source();
  ClassMap class_map;
  try {
    class_map = ClassMap::parse(options_.class_map);
  } catch (const ClassMapError& e) {
    throw core::ConfigError("class_map in " + where + ": " + e.what());
  }
  try {
    if (options_.detector == "onnx_yolo")
      return std::make_unique<OnnxYoloDetector>(options_.onnx_yolo, class_map);
    if (options_.detector == "hog")
      return std::make_unique<HogPeopleDetector>(options_.hog, class_map);
    if (options_.ground_truth.objects.empty())
      throw DetectorError("objects is empty: set it to dynslam-sim's objects.txt");
    return std::make_unique<GroundTruthDetector>(options_.ground_truth, class_map);
  } catch (const std::runtime_error& e) {  // DetectorError, ObjectGroundTruthError
    throw core::ConfigError(options_.detector + " detector, " + where + ": " + e.what());
  }
}

void DetectionStage::process(core::Frame& frame) {
  if (frames_ == 0) first_t_ = frame.t;
  last_t_ = frame.t;
  ++frames_;
  frame.detections.clear();
  frame.detections_fresh = false;
  if (detector_) {
    frame.detections = detector_->detect(frame);
    frame.detections_fresh = true;
    ++fresh_frames_;
    recordSource(frame.index);
    return;
  }
  // Take what finished first, then leave this frame for the detector: it is the newest image,
  // the one worth detecting next.
  if (auto result = realtime_->poll()) {
    frame.detections = std::move(result->detections);
    frame.detections_fresh = true;
    ++fresh_frames_;
    recordSource(result->frame_index);
    realtime_detector_seconds_ += result->seconds;
  }
  realtime_->submit(frame);
}

void DetectionStage::recordSource(std::size_t frame_index) {
  // Bounded over a long run: the oldest half goes once twice the kept number is reached.
  if (source_frames_.size() >= 2 * kSourceFramesKept)
    source_frames_.erase(source_frames_.begin(),
                         source_frames_.begin() + std::ptrdiff_t(kSourceFramesKept));
  source_frames_.push_back(frame_index);
}

void DetectionStage::finish() {
  statistics_ = {{"frames", double(frames_)}, {"fresh_frames", double(fresh_frames_)}};
  if (realtime_) {
    const std::size_t runs = realtime_->completed(), dropped = realtime_->dropped();
    realtime_.reset();  // joins the thread; a result still under way is dropped
    const double span = last_t_ - first_t_;
    const double hz = span > 0 ? runs / span : 0.0;
    const double ms = fresh_frames_ ? 1000.0 * realtime_detector_seconds_ / fresh_frames_ : 0.0;
    statistics_.insert(statistics_.end(), {{"detector_runs", double(runs)},
                                           {"detector_hz", hz},
                                           {"detector_ms", ms},
                                           {"superseded", double(dropped)}});
    MRPT_LOG_INFO_STREAM("real-time detection: "
                         << fresh_frames_ << " of " << frames_ << " frames got fresh "
                         << "detections; detector ran " << runs << " times (" << hz
                         << " per second of stream), " << ms << " ms per run; " << dropped
                         << " results superseded before a frame took them");
  } else {
    MRPT_LOG_INFO_STREAM(fresh_frames_ << " frames detected inline");
  }
}

std::vector<std::pair<std::string, double>> DetectionStage::statistics() const {
  return statistics_;
}

}  // namespace dynslam::detection
