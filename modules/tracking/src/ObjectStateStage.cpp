#include "dynslam/tracking/ObjectStateStage.h"

#include <dynslam/segmentation/FloorPlane.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace dynslam::tracking {

void ObjectStateOptions::describe(core::OptionVisitor& v) {
  using core::Range;
  auto& c = centre;
  v.key("pixel_stride", c.pixel_stride, Range::atLeast(1),
        "px; every this-th mask pixel in x and y is measured");
  v.key("min_points", c.min_points, Range::atLeast(1),
        "mask pixels with depth an object needs to be measured in a frame");
  v.key("thickness_fraction", c.thickness_fraction, Range::atLeast(0),
        "the body's unseen depth along the line of sight / its seen width: the centre lies "
        "half of it behind the seen surface");
  v.key("max_thickness_m", c.max_thickness_m, Range::atLeast(0), "m; that depth at most");
  v.key("sigma_across_m", c.sigma_across_m, Range::above(0),
        "m; a measured centre's sigma across the line of sight");
  v.key("sigma_along_m", c.sigma_along_m, Range::above(0), "m; along the line of sight");
  v.key("sigma_up_m", c.sigma_up_m, Range::above(0), "m; along up");
  v.key("acceleration_sigma", acceleration_sigma, Range::above(0),
        "m/s^2/sqrt(Hz); white-noise acceleration of a body's centre");
  v.key("maneuver_acceleration_sigma", maneuver_acceleration_sigma, Range::above(0),
        "m/s^2/sqrt(Hz); the acceleration noise of a body whose measurements disagree with its "
        "state (turning, stopping)");
  v.key("maneuver_nis", maneuver_nis, Range::atLeast(0),
        "0 = off; a state whose mean normalised innovation squared over about five frames "
        "exceeds this moves with maneuver_acceleration_sigma (3 dof: 3 when consistent)");
  v.key("initial_speed_sigma", initial_speed_sigma, Range::above(0),
        "m/s; a new state starts at rest with this sigma");
  v.key("max_coast_s", max_coast_s, Range::atLeast(0),
        "s; an object not measured for longer is dropped");
  v.key("reassociation_distance_m", reassociation_distance_m, Range::atLeast(0),
        "m; a new track this close (on the ground plane) to an unmeasured state's prediction "
        "continues it");
  v.key("gate_chi2", gate_chi2, Range::atLeast(0),
        "0 = off; a track's measurement whose squared Mahalanobis distance from its state "
        "exceeds this starts a new state (3 dof)");
  v.key("gate_frames", gate_frames, Range::atLeast(1),
        "with gate_chi2: measurements outside the gate in a row that part a track from its "
        "state (fewer are skipped)");
  v.key("moving_speed", moving_speed, Range::atLeast(0),
        "m/s; a state faster than this on the ground plane is moving");
  v.key("confirmed_only", confirmed_only, "only confirmed tracks are measured");
  v.key("extent_smoothing", extent_smoothing, Range::closed(0, 1),
        "weight of a frame's extent in the state's running mean");
}

void ObjectStateStage::configure(const core::IniConfig& cfg, const std::string& section) {
  core::loadOptionsStrict(options_, cfg, section);
}

void ObjectStateStage::process(core::Frame& frame) {
  ++frames_;
  if (last_t_ && frame.t > *last_t_)
    for (auto& s : followed_) {
      const bool maneuvering = options_.maneuver_nis > 0 && s.nis > options_.maneuver_nis;
      ++predictions_;
      maneuvering_ += maneuvering;
      s.filter.predict(frame.t - *last_t_, maneuvering ? options_.maneuver_acceleration_sigma
                                                       : options_.acceleration_sigma);
    }
  if (!last_t_ || frame.t > *last_t_) last_t_ = frame.t;
  for (auto& s : followed_) s.measured = false;

  if (frame.T_world_camera) {
    // The world's up: the mean of every posed frame's up (accelerometer, else image) so far.
    up_sum_ += (frame.T_world_camera->linear() * segmentation::upInCamera(frame)).normalized();
    up_ = up_sum_.normalized();
    auto measurements = measure(frame, up_);
    measurements_ += measurements.size();
    associate(measurements, frame.t);
  }
  const std::size_t before = followed_.size();
  followed_.erase(std::remove_if(followed_.begin(), followed_.end(),
                                 [&](const Followed& s) {
                                   return frame.t - s.last_measured > options_.max_coast_s;
                                 }),
                  followed_.end());
  expired_ += before - followed_.size();
  frame.object_states = states();
}

std::vector<ObjectStateStage::Measurement> ObjectStateStage::measure(
    const core::Frame& frame, const Eigen::Vector3d& up_world) const {
  const Eigen::Isometry3d& T = *frame.T_world_camera;
  const Eigen::Vector3d up_camera = T.linear().transpose() * up_world;
  std::map<int, Measurement> by_track;  // a track segmented twice keeps its larger mask
  for (const auto& mask : frame.object_masks) {
    if (!mask.valid || mask.track < 0 || mask.track >= int(frame.tracks.size())) continue;
    const core::Track& track = frame.tracks[size_t(mask.track)];
    if (options_.confirmed_only && track.state != core::TrackState::Confirmed) continue;
    const auto c =
        measureObjectCentre(frame.depth, frame.intrinsics, mask, up_camera, options_.centre);
    if (!c) continue;
    auto it = by_track.find(track.id);
    if (it != by_track.end() && it->second.points >= c->points) continue;
    by_track[track.id] = {track.id,      track.category,
                          T * c->centre, T.linear() * c->covariance * T.linear().transpose(),
                          c->extent,     c->points};
  }
  std::vector<Measurement> out;
  for (auto& [id, m] : by_track) out.push_back(std::move(m));
  return out;
}

Eigen::Vector3d ObjectStateStage::horizontal(const Eigen::Vector3d& v) const {
  return v - v.dot(up_) * up_;
}

void ObjectStateStage::associate(std::vector<Measurement>& measurements, double t) {
  // 1. Each state takes its own track's measurement. One outside the gate is skipped; gate_frames
  // in a row part the track from the state (its id moved to another body), which coasts on.
  std::vector<bool> used(measurements.size(), false);
  for (auto& s : followed_) {
    for (std::size_t i = 0; i < measurements.size(); ++i) {
      if (used[i] || measurements[i].track_id != s.track_id) continue;
      const double nis = s.filter.mahalanobis2(measurements[i].centre, measurements[i].covariance);
      if (options_.gate_chi2 > 0 && nis > options_.gate_chi2) {
        if (++s.outliers < options_.gate_frames) {
          used[i] = true;  // skipped: neither this state's nor a new one's
          break;
        }
        s.track_id = -1;
        s.outliers = 0;
        ++gated_;
        break;
      }
      update(s, measurements[i], nis, t);
      used[i] = true;
    }
  }
  // 2. A track no state has followed yet continues the nearest unmeasured state of its category
  // (the tracker lost the body and made a new track on it), else starts one. Greedy by distance,
  // nearest pair first.
  std::vector<std::tuple<double, std::size_t, std::size_t, double>> pairs;  // d, i, k, NIS
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    if (used[i] || followed_tracks_.count(measurements[i].track_id)) continue;
    for (std::size_t k = 0; k < followed_.size(); ++k) {
      const Followed& s = followed_[k];
      if (s.measured || s.category != measurements[i].category) continue;
      const double d = horizontal(s.filter.position() - measurements[i].centre).norm();
      const double nis = s.filter.mahalanobis2(measurements[i].centre, measurements[i].covariance);
      const bool inGate = options_.gate_chi2 <= 0 || nis <= options_.gate_chi2;
      if (d <= options_.reassociation_distance_m && inGate) pairs.emplace_back(d, i, k, nis);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [d, i, k, nis] : pairs) {
    if (used[i] || followed_[k].measured) continue;
    followed_[k].track_id = measurements[i].track_id;
    followed_tracks_.insert(measurements[i].track_id);
    update(followed_[k], measurements[i], nis, t);
    used[i] = true;
    ++reassociated_;
  }
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    if (used[i]) continue;
    const Measurement& m = measurements[i];
    followed_tracks_.insert(m.track_id);
    followed_.push_back(
        {next_id_++, m.track_id, m.category,
         ConstantVelocityFilter(m.centre, m.covariance, options_.initial_speed_sigma), m.extent, t,
         true, 0, 0.0});
  }
}

void ObjectStateStage::update(Followed& state, const Measurement& m, double nis, double t) {
  state.nis = 0.8 * state.nis + 0.2 * nis;  // fading memory of about five frames
  state.filter.update(m.centre, m.covariance);
  const double w = options_.extent_smoothing;
  state.extent = (1 - w) * state.extent + w * m.extent;
  state.last_measured = t;
  state.measured = true;
  state.outliers = 0;
}

std::vector<core::ObjectState> ObjectStateStage::states() const {
  std::vector<core::ObjectState> out;
  for (const auto& s : followed_) {
    core::ObjectState o;
    o.id = s.id;
    o.track_id = s.track_id;
    o.category = s.category;
    o.centre = s.filter.position();
    o.velocity = s.filter.velocity();
    o.extent = s.extent;
    o.covariance = s.filter.covariance();
    o.up = up_;
    o.last_measured = s.last_measured;
    o.measured = s.measured;
    o.moving = horizontal(o.velocity).norm() > options_.moving_speed;
    out.push_back(std::move(o));
  }
  return out;
}

void ObjectStateStage::finish() {
  MRPT_LOG_INFO_STREAM(next_id_ << " object states over " << frames_ << " frames; " << reassociated_
                                << " continued by a new track, " << gated_
                                << " left by their track");
}

std::vector<std::pair<std::string, double>> ObjectStateStage::statistics() const {
  return {
      {"frames", double(frames_)},
      {"states", double(next_id_)},
      {"measurements", double(measurements_)},
      {"reassociated", double(reassociated_)},
      {"gated", double(gated_)},
      {"expired", double(expired_)},
      {"maneuvering_fraction", predictions_ ? double(maneuvering_) / double(predictions_) : 0.0}};
}

}  // namespace dynslam::tracking
