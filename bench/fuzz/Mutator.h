#pragma once
// Mutations of a valid input file for bench-fuzz-inputs: what a failing disk, a cut download or
// a buggy recorder does to a file (flipped bits, overwritten bytes, truncation, repeated and
// swapped blocks, a length field turned huge) and, for text, what a careless edit does (a number
// turned NaN or enormous, lines lost, repeated or swapped, stray bytes).
#include <cstdint>
#include <random>
#include <string>

namespace dynslam::bench::fuzz {

struct Mutation {
  std::string bytes;  ///< the mutated file
  std::string what;   ///< the edits made, e.g. "truncate at 1203 of 88140; flip 3 bits"
};

class Mutator {
 public:
  explicit Mutator(uint64_t seed) : rng_(seed) {}

  /// One to three edits of `input`; `text` adds the line and number edits to the binary ones.
  Mutation mutate(const std::string& input, bool text);

 private:
  size_t below(size_t n) { return n ? std::uniform_int_distribution<size_t>(0, n - 1)(rng_) : 0; }
  std::string flipBits(std::string& s);
  std::string overwriteBytes(std::string& s);
  std::string truncate(std::string& s);
  std::string repeatBlock(std::string& s);
  std::string swapBlocks(std::string& s);
  std::string hugeLength(std::string& s);
  std::string editNumber(std::string& s);
  std::string editLines(std::string& s);
  std::string insertBytes(std::string& s);

  std::mt19937_64 rng_;
};

}  // namespace dynslam::bench::fuzz
