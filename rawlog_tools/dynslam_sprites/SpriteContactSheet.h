#pragma once
// A picture of a sprite bank: one row per sequence, up to eight of its frames composited on grey
// at one height, captioned with the sequence's number, length and gait cycles.
#include <dynslam/sim/SpriteBank.h>

#include <string>

/// Throws std::runtime_error naming the file when it cannot be written.
void writeSpriteContactSheet(const dynslam::sim::SpriteBank& bank, const std::string& png);
