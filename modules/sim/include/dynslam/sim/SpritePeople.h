#pragma once
// Real-appearance people ([People] appearance = video): each person of a scene wears one walking
// sequence of a sprite bank (dynslam-sprites) at a height of 1.55-1.90 m instead of the rendered
// body, drawn into every frame by compositeSprite: its walking cycle advanced by the distance
// walked, mirrored to match the walking direction, z-tested against the real or rendered depth
// and the other people, and scored in the ground truth as rendered people are.
#include <dynslam/sim/Agent.h>
#include <dynslam/sim/SpriteBank.h>

#include <random>
#include <string>
#include <vector>

namespace dynslam::sim {

class SpritePeople {
 public:
  /// Reads the bank (std::runtime_error naming the folder when it is missing or broken).
  explicit SpritePeople(const std::string& bank_dir);

  /// Gives every person of `agents` a sequence and a height drawn from `rng`.
  void dress(std::vector<Agent>& agents, std::mt19937_64& rng) const;

  /// Draws the dressed people of `agents` at time t into `frame` and returns their ground truth
  /// (amodal box, visible pixels in the final label image, visible fraction), in agent order.
  std::vector<ObjectTruth> draw(const std::vector<Agent>& agents, double t,
                                const core::CameraIntrinsics& camera,
                                const Eigen::Isometry3d& T_world_camera,
                                RenderOutput& frame) const;

 private:
  /// The frame of the person's sequence at time t (walking along `heading`), and whether to
  /// mirror it.
  const SpriteFrame& frameAt(const Agent& agent, double t, double heading,
                             const Eigen::Isometry3d& T_world_camera, bool& mirrored) const;

  SpriteBank bank_;
};

/// Adds `more` to `truths`, keeping them ordered by id (objects.txt lists a frame's objects so).
void appendInIdOrder(std::vector<ObjectTruth>& truths, const std::vector<ObjectTruth>& more);

}  // namespace dynslam::sim
