#include "Mutator.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <vector>

namespace dynslam::bench::fuzz {

Mutation Mutator::mutate(const std::string& input, bool text) {
  using Edit = std::string (Mutator::*)(std::string&);
  static const std::vector<Edit> binary = {&Mutator::flipBits,   &Mutator::overwriteBytes,
                                           &Mutator::truncate,   &Mutator::repeatBlock,
                                           &Mutator::swapBlocks, &Mutator::hugeLength};
  static const std::vector<Edit> textual = {&Mutator::editNumber, &Mutator::editNumber,
                                            &Mutator::editLines, &Mutator::editLines,
                                            &Mutator::insertBytes};
  Mutation m{input, ""};
  const size_t edits = 1 + below(3);
  for (size_t i = 0; i < edits && !m.bytes.empty(); ++i) {
    const bool useText = text && below(2) == 0;
    const auto& pool = useText ? textual : binary;
    const std::string what = (this->*pool[below(pool.size())])(m.bytes);
    m.what += (m.what.empty() ? "" : "; ") + what;
  }
  return m;
}

std::string Mutator::flipBits(std::string& s) {
  const size_t n = 1 + below(8);
  for (size_t i = 0; i < n; ++i) s[below(s.size())] ^= char(1u << below(8));
  return "flip " + std::to_string(n) + " bits";
}

std::string Mutator::overwriteBytes(std::string& s) {
  static const unsigned char values[] = {0x00, 0xff, 0x7f, 0x80, 0x88, '\n', '-'};
  const size_t n = 1 + below(4);
  for (size_t i = 0; i < n; ++i)
    s[below(s.size())] = below(4) ? char(values[below(sizeof values)]) : char(below(256));
  return "overwrite " + std::to_string(n) + " bytes";
}

std::string Mutator::truncate(std::string& s) {
  const size_t size = s.size(), at = below(size);
  s.resize(at);
  return "truncate at " + std::to_string(at) + " of " + std::to_string(size);
}

std::string Mutator::repeatBlock(std::string& s) {
  const size_t at = below(s.size()), length = 1 + below(std::min<size_t>(4096, s.size() - at));
  s.insert(at + length, s.substr(at, length));
  return "repeat " + std::to_string(length) + " bytes at " + std::to_string(at);
}

std::string Mutator::swapBlocks(std::string& s) {
  if (s.size() < 4) return flipBits(s);
  const size_t length = 1 + below(std::min<size_t>(4096, s.size() / 2));
  const size_t a = below(s.size() - 2 * length + 1);
  const size_t b = a + length + below(s.size() - a - 2 * length + 1);
  std::swap_ranges(s.begin() + long(a), s.begin() + long(a + length), s.begin() + long(b));
  return "swap " + std::to_string(length) + " bytes at " + std::to_string(a) + " and " +
         std::to_string(b);
}

/// A little-endian 32-bit value between 1 and 2^20 is likely a size, a count or an image
/// dimension: one of them, found by sampling, becomes huge (2^30 .. 2^32 - 1).
std::string Mutator::hugeLength(std::string& s) {
  if (s.size() < 4) return flipBits(s);
  static const uint32_t huge[] = {0xffffffffu, 0x7fffffffu, 0x80000000u, 0x40000000u, 0xfffffff0u};
  for (int tries = 0; tries < 2000; ++tries) {
    const size_t at = below(s.size() - 3);
    uint32_t v = 0;
    std::memcpy(&v, s.data() + at, 4);
    if (v < 1 || v > (1u << 20)) continue;
    const uint32_t h = huge[below(sizeof huge / sizeof huge[0])];
    std::memcpy(s.data() + at, &h, 4);
    return "length " + std::to_string(v) + " at " + std::to_string(at) + " -> " + std::to_string(h);
  }
  return overwriteBytes(s);
}

std::string Mutator::editNumber(std::string& s) {
  static const char* replacements[] = {
      "nan",        "inf",    "-inf", "1e308", "-1",   "0", "-0", "99999999999999999999",
      "4294967296", "1e-320", "",     "1.2.3", "0x10", "+", "  "};
  std::vector<std::pair<size_t, size_t>> numbers;  // [begin, end)
  for (size_t i = 0; i < s.size();) {
    if (std::isdigit(static_cast<unsigned char>(s[i]))) {
      size_t j = i;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                              s[j] == 'e' || s[j] == '-'))
        ++j;
      numbers.emplace_back(i, j);
      i = j;
    } else {
      ++i;
    }
  }
  if (numbers.empty()) return insertBytes(s);
  const auto [b, e] = numbers[below(numbers.size())];
  const std::string r = replacements[below(sizeof replacements / sizeof replacements[0])];
  const std::string was = s.substr(b, e - b);
  s.replace(b, e - b, r);
  return "number '" + was + "' -> '" + r + "'";
}

std::string Mutator::editLines(std::string& s) {
  std::vector<std::string> lines;
  for (size_t b = 0; b < s.size();) {
    const size_t e = std::min(s.find('\n', b), s.size());
    lines.push_back(s.substr(b, e - b + (e < s.size() ? 1 : 0)));
    b = e + 1;
  }
  if (lines.size() < 2) return insertBytes(s);
  const size_t a = below(lines.size()), c = below(lines.size());
  std::string what;
  switch (below(3)) {
    case 0:
      lines.erase(lines.begin() + long(a));
      what = "delete line " + std::to_string(a + 1);
      break;
    case 1:
      lines.insert(lines.begin() + long(a), lines[a]);
      what = "repeat line " + std::to_string(a + 1);
      break;
    default:
      std::swap(lines[a], lines[c]);
      what = "swap lines " + std::to_string(a + 1) + " and " + std::to_string(c + 1);
  }
  s.clear();
  for (const auto& l : lines) s += l;
  return what;
}

std::string Mutator::insertBytes(std::string& s) {
  const size_t n = 1 + below(16), at = below(s.size() + 1);
  std::string bytes;
  for (size_t i = 0; i < n; ++i) bytes += char(below(256));
  s.insert(at, bytes);
  return "insert " + std::to_string(n) + " bytes at " + std::to_string(at);
}

}  // namespace dynslam::bench::fuzz
