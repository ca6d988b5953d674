#include "nav_demo/GroundTruthSource.h"

#include <dynslam/system/PoseConversion.h>
#include <mrpt/maps/CSimplePointsMap.h>

namespace dynslam::navdemo {
using system::toTPose3D;

system::MovingObject trueObject(const sim::Agent& agent, double t, double stamp) {
  const double h = 0.05;
  const Eigen::Vector3d c = sim::agentStateAt(agent, t).T_world_core.translation();
  const Eigen::Vector3d v = (sim::agentStateAt(agent, t + h).T_world_core.translation() -
                             sim::agentStateAt(agent, t - h).T_world_core.translation()) /
                            (2 * h);
  system::MovingObject o;
  o.id = agent.id;
  o.category = sim::categoryName(agent.kind);
  o.pose = mrpt::math::TPose3D(c.x(), c.y(), c.z(), 0, 0, 0);
  o.velocity = {v.x(), v.y(), v.z()};
  const bool car = agent.kind == sim::AgentKind::Car;
  o.extent = car ? mrpt::math::TPoint3D(1.8, 1.5, 4.4) : mrpt::math::TPoint3D(0.5, 2 * c.z(), 0.3);
  o.moving = sim::agentStateAt(agent, t).moving;
  o.measured = true;
  o.last_seen = mrpt::Clock::fromDouble(stamp);
  return o;
}

GroundTruthSource::GroundTruthSource(const std::vector<sim::Agent>& agents,
                                     const StaticFootprint& statics)
    : agents_(agents) {
  auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
  for (const auto& p : statics.occupiedCells())
    for (double z = 0.1; z < 2.0; z += 0.3) map->insertPoint(p.x(), p.y(), z);
  map_ = map;
}

void GroundTruthSource::update(double t, double stamp, const Eigen::Isometry3d& T_world_camera) {
  system::LocalizationUpdate u;
  u.timestamp = mrpt::Clock::fromDouble(stamp);
  u.pose = toTPose3D(T_world_camera);
  std::lock_guard<std::mutex> lock(mutex_);
  poses_.add(u);
  t_ = t;
  stamp_ = stamp;
}

system::TrackingStatus GroundTruthSource::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return poses_.latest ? system::TrackingStatus::Tracking : system::TrackingStatus::Initializing;
}

nav::CameraPoses GroundTruthSource::cameraPoses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return poses_;
}

std::vector<system::MovingObject> GroundTruthSource::movingObjects() const {
  double t, stamp;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    t = t_, stamp = stamp_;
  }
  std::vector<system::MovingObject> out;
  for (const auto& agent : agents_) out.push_back(trueObject(agent, t, stamp));
  return out;
}

}  // namespace dynslam::navdemo
