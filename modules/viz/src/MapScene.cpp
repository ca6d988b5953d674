#include "dynslam/viz/MapScene.h"

#include "dynslam/viz/IdColours.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/Thinning.h>

#include <mrpt/maps/CColouredPointsMap.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/stock_objects.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace dynslam::viz {
namespace {

/// 21 bits per axis (+-1 million voxels, +-52 km at 5 cm): enough for any run.
std::uint64_t voxelKey(const Eigen::Vector3f& p, float inverse_size) {
  constexpr std::int64_t kOffset = 1 << 20;
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  const auto axis = [&](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inverse_size)) +
                                      kOffset) &
           kMask;
  };
  return axis(p.x()) | (axis(p.y()) << 21) | (axis(p.z()) << 42);
}

/// 255 where a pixel belongs (or may belong) to an object; grown by a pixel or two because the
/// depth-threshold masks miss the mixed-depth pixels along an object's outline.
cv::Mat objectPixels(const core::Frame& f, cv::Size size) {
  cv::Mat objects(size, CV_8UC1, cv::Scalar(0));
  const cv::Rect whole({0, 0}, size);
  std::vector<bool> masked(f.tracks.size(), false);
  for (const auto& m : f.object_masks) {
    if (m.track >= 0 && m.track < static_cast<int>(masked.size()) && m.valid)
      masked[static_cast<size_t>(m.track)] = true;
    const cv::Rect roi = m.roi & whole;
    if (!m.valid || m.mask.empty() || roi != m.roi || roi.size() != m.mask.size()) continue;
    objects(roi).setTo(255, m.mask);
  }
  for (size_t i = 0; i < f.tracks.size(); ++i) {
    const auto& t = f.tracks[i];
    if (t.state == core::TrackState::Lost || masked[i]) continue;
    const cv::Rect box = cv::Rect(t.box) & whole;
    if (!box.empty()) objects(box).setTo(255);
  }
  cv::dilate(objects, objects, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
  return objects;
}

mrpt::opengl::CSetOfLines::Ptr polyline(const std::vector<Eigen::Vector3f>& points,
                                        const std::string& name, const cv::Scalar& bgr,
                                        float width) {
  auto lines = mrpt::opengl::CSetOfLines::Create();
  lines->setName(name);
  lines->setLineWidth(width);
  lines->setColor_u8(static_cast<uint8_t>(bgr[2]), static_cast<uint8_t>(bgr[1]),
                     static_cast<uint8_t>(bgr[0]));
  // A track seen at one frame only is still a (zero-length) segment, so that it is findable.
  if (points.size() == 1)
    lines->appendLine(points[0].x(), points[0].y(), points[0].z(), points[0].x(), points[0].y(),
                      points[0].z());
  for (size_t i = 1; i < points.size(); ++i) {
    const auto& a = points[i - 1];
    const auto& b = points[i];
    lines->appendLine(a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  }
  return lines;
}

}  // namespace

std::string objectTrackName(int id) { return "object_" + std::to_string(id); }

MapSceneBuilder::MapSceneBuilder(MapSceneOptions options) : options_(options) {
  if (options_.every_n_frames < 1 || options_.pixel_stride < 1 || !(options_.voxel_size > 0) ||
      options_.max_track_points < 2)
    throw std::invalid_argument(
        "MapSceneBuilder: every_n_frames and pixel_stride must be >= 1, voxel_size > 0 and "
        "max_track_points >= 2");
}

void MapSceneBuilder::appendToTrack(std::vector<Eigen::Vector3f>& track,
                                    const Eigen::Vector3f& point) const {
  track.push_back(point);
  if (track.size() <= options_.max_track_points) return;
  // Every second point, the first and the newest kept: the line's extent stays whole.
  core::keepEverySecond(track);
  track.shrink_to_fit();
}

void MapSceneBuilder::addFrame(const core::Frame& frame) {
  if (frame.object_states) {
    for (const auto& s : *frame.object_states)
      appendToTrack(objects_[s.id], s.centre.cast<float>());
  } else {
    for (const auto& o : frame.object_poses)
      appendToTrack(objects_[o.object_id], o.T_world_object.translation().cast<float>());
  }
  if (!frame.T_world_camera) return;
  appendToTrack(camera_, frame.T_world_camera->translation().cast<float>());
  if (posed_frames_++ % static_cast<size_t>(options_.every_n_frames) == 0) addStaticPoints(frame);
}

void MapSceneBuilder::addStaticPoints(const core::Frame& f) {
  const auto& k = f.intrinsics;
  if (f.depth.empty() || f.depth.type() != CV_32FC1 || k.fx <= 0 || k.fy <= 0) return;
  ++static_updates_;
  const bool colour = !f.rgb.empty() && f.rgb.size() == f.depth.size() && f.rgb.type() == CV_8UC3;
  const cv::Mat objects = objectPixels(f, f.depth.size());
  const Eigen::Isometry3f T = f.T_world_camera->cast<float>();
  const float inverse_size = static_cast<float>(1.0 / options_.voxel_size);
  const int s = options_.pixel_stride;
  for (int v = s / 2; v < f.depth.rows; v += s) {
    const float* depth = f.depth.ptr<float>(v);
    const uint8_t* object = objects.ptr<uint8_t>(v);
    for (int u = s / 2; u < f.depth.cols; u += s) {
      const float z = depth[u];
      if (!(z > 0) || z > options_.max_depth || object[u]) continue;
      const Eigen::Vector3f p = T * Eigen::Vector3f(static_cast<float>((u - k.cx) / k.fx) * z,
                                                    static_cast<float>((v - k.cy) / k.fy) * z, z);
      const std::uint64_t key = voxelKey(p, inverse_size);
      auto it = voxels_.find(key);
      if (it == voxels_.end()) {
        if (voxels_.size() >= options_.max_points) {
          ++points_refused_;
          continue;
        }
        it = voxels_.emplace(key, Voxel{}).first;
      }
      Voxel& voxel = it->second;
      voxel.position_sum += p;
      if (colour) {
        const auto& c = f.rgb.at<cv::Vec3b>(v, u);
        voxel.bgr_sum += Eigen::Vector3f(c[0], c[1], c[2]);
      } else {
        voxel.bgr_sum += Eigen::Vector3f::Constant(160.f);
      }
      ++voxel.count;
      if (voxel.last_update != static_updates_) {
        voxel.last_update = static_cast<std::uint32_t>(static_updates_);
        ++voxel.frames;
      }
    }
  }
}

void MapSceneBuilder::save(const std::string& path) const {
  mrpt::opengl::COpenGLScene scene;
  fill(scene);
  core::replaceFileAtomically(path, [&](const std::string& temporary) {
    if (!scene.saveToFile(temporary))
      throw std::runtime_error("cannot write the map scene '" + path + "'");
  });
}

namespace {

/// Each voxel's point: its mean position and mean colour (r, g, b in [0, 1]), in map order; only
/// voxels hit in at least `min_frames` frames.
template <class Voxels, class Add>
void forEachVoxelPoint(const Voxels& voxels, int min_frames, Add&& add) {
  for (const auto& [key, voxel] : voxels) {
    if (static_cast<int>(voxel.frames) < min_frames) continue;
    const Eigen::Vector3f p = voxel.position_sum / static_cast<float>(voxel.count);
    const Eigen::Vector3f bgr = voxel.bgr_sum / (255.f * static_cast<float>(voxel.count));
    add(p, bgr.z(), bgr.y(), bgr.x());
  }
}

}  // namespace

std::shared_ptr<mrpt::maps::CColouredPointsMap> MapSceneBuilder::staticPoints() const {
  auto map = std::make_shared<mrpt::maps::CColouredPointsMap>();
  map->reserve(voxels_.size());
  forEachVoxelPoint(voxels_, options_.min_frames,
                    [&](const Eigen::Vector3f& p, float r, float g, float b) {
                      map->insertPointRGB(p.x(), p.y(), p.z(), r, g, b);
                    });
  return map;
}

void MapSceneBuilder::fill(mrpt::opengl::COpenGLScene& scene) const {
  auto cloud = mrpt::opengl::CPointCloudColoured::Create();
  cloud->setName(kStaticMapName);
  cloud->setPointSize(2.0f);
  cloud->reserve(voxels_.size());
  forEachVoxelPoint(voxels_, 1, [&](const Eigen::Vector3f& p, float r, float g, float b) {
    cloud->push_back(p.x(), p.y(), p.z(), r, g, b);
  });
  scene.insert(cloud);
  // Black: no object colour is dark (IdColours keeps every channel >= 64).
  scene.insert(polyline(camera_, kCameraTrajectoryName, {0, 0, 0}, 2.0f));
  for (const auto& [id, points] : objects_)
    scene.insert(polyline(points, objectTrackName(id), colourForId(id), 2.0f));
  auto origin = mrpt::opengl::stock_objects::CornerXYZSimple(0.3f, 2.0f);
  origin->setName("world_origin");
  scene.insert(origin);
}

}  // namespace dynslam::viz
