#pragma once
// Random numbers whose values do not depend on the standard library's implementation (the
// std:: distributions' outputs are implementation-defined): the same ini and seed must give
// the same scene everywhere.
#include <cstdint>
#include <random>

namespace dynslam::sim {

/// A uniform double in [lo, hi) from the generator's top 53 bits.
inline double uniformReal(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// The independent random streams of one simulated run (see subSeed): the same numbering in every
/// sequence source, so a stream means the same thing in the Simulator and the Augmenter.
enum RandomStream : uint64_t {
  kSceneStream = 0,     ///< layout, textures, agents
  kImuStream = 1,       ///< IMU noise and bias walk
  kGnssStream = 2,      ///< GNSS noise
  kFloorStream = 3,     ///< augment mode's floor RANSAC
  kSpriteStream = 4,    ///< which sprite sequence and height each real-appearance person takes
  kFrameStreams = 1000  ///< + frame index: that frame's image noise
};

/// A seed for stream `stream` of a run seeded with `seed` (splitmix64 of both), so that frame
/// i's noise, the IMU's noise and the scene's layout are independent and each reproducible.
inline uint64_t subSeed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace dynslam::sim
