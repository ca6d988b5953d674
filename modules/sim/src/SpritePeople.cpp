#include <dynslam/sim/SpriteCompositor.h>
#include <dynslam/sim/SpritePeople.h>

#include "dynslam/sim/Random.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>

namespace dynslam::sim {

SpritePeople::SpritePeople(const std::string& bank_dir) : bank_(readSpriteBank(bank_dir)) {}

void SpritePeople::dress(std::vector<Agent>& agents, std::mt19937_64& rng) const {
  for (auto& agent : agents) {
    if (agent.kind != AgentKind::Person) continue;
    agent.sprite_sequence =
        std::min(int(bank_.sequences.size()) - 1, int(uniformReal(rng, 0, bank_.sequences.size())));
    agent.sprite_height_m = uniformReal(rng, 1.55, 1.90);
  }
}

const SpriteFrame& SpritePeople::frameAt(const Agent& agent, double t, double heading,
                                         const Eigen::Isometry3d& T_world_camera,
                                         bool& mirrored) const {
  const SpriteSequence& seq = bank_.sequences.at(size_t(agent.sprite_sequence));
  mirrored = false;
  if (agent.path.standing()) return seq.frames.front();
  // The cycle advances with the distance walked: the frame whose walked distance (scaled to
  // this person's height) is the distance walked, looping over the sequence.
  const double loop = seq.frames.back().walked_heights * agent.sprite_height_m;
  const double walked = loop > 0 ? std::fmod(agent.path.distance(t), loop) : 0.0;
  size_t k = 0;
  while (k + 1 < seq.frames.size() &&
         seq.frames[k + 1].walked_heights * agent.sprite_height_m <= walked)
    ++k;
  // Mirrored when the person walks the other way across the image than the sprite's walker.
  const Eigen::Vector3d dir(std::cos(heading), std::sin(heading), 0);
  const double across = (T_world_camera.linear().transpose() * dir).x();
  mirrored = across * seq.footVelocity().x < 0;
  return seq.frames[k];
}

std::vector<ObjectTruth> SpritePeople::draw(const std::vector<Agent>& agents, double t,
                                            const core::CameraIntrinsics& camera,
                                            const Eigen::Isometry3d& T_world_camera,
                                            RenderOutput& frame) const {
  std::vector<std::pair<size_t, SpriteDraw>> drawn;
  for (size_t i = 0; i < agents.size(); ++i) {
    const Agent& agent = agents[i];
    if (agent.sprite_sequence < 0) continue;
    Eigen::Vector2d xy;
    double heading = 0;
    agent.path.at(t, xy, heading);
    SpritePlacement placement;
    const SpriteFrame& sprite = frameAt(agent, t, heading, T_world_camera, placement.mirrored);
    placement.foot_world = Eigen::Vector3d(xy.x(), xy.y(), 0);
    placement.height_m = agent.sprite_height_m;
    const SpriteDraw d =
        compositeSprite(sprite, placement, agent.id, camera, T_world_camera, frame);
    if (d.pixels > 0) drawn.emplace_back(i, d);
  }
  // Visible pixels from the final labels: a person drawn later in front hides one drawn before.
  std::vector<ObjectTruth> truths;
  for (const auto& [i, d] : drawn) {
    ObjectTruth truth;
    truth.id = agents[i].id;
    truth.category = categoryName(agents[i].kind);
    const AgentState state = agentStateAt(agents[i], t);
    truth.moving = state.moving;
    truth.T_world_object = state.T_world_core;
    truth.box = d.box;
    truth.visible_pixels = cv::countNonZero(frame.label(d.box) == truth.id);
    truth.visible_fraction = std::min(1.0, truth.visible_pixels / double(d.pixels));
    truths.push_back(truth);
  }
  return truths;
}

void appendInIdOrder(std::vector<ObjectTruth>& truths, const std::vector<ObjectTruth>& more) {
  if (more.empty()) return;
  truths.insert(truths.end(), more.begin(), more.end());
  std::stable_sort(truths.begin(), truths.end(),
                   [](const ObjectTruth& a, const ObjectTruth& b) { return a.id < b.id; });
}

}  // namespace dynslam::sim
