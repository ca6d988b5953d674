#include "sweep/SweepGrid.h"

#include <algorithm>

namespace dynslam::sweep {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t at; (at = s.find(sep, start)) != std::string::npos; start = at + 1)
    parts.push_back(s.substr(start, at - start));
  parts.push_back(s.substr(start));
  return parts;
}

}  // namespace

std::vector<SweptKey> parseGrid(const std::string& text) {
  std::vector<SweptKey> keys;
  for (const std::string& raw : split(text, ';')) {
    const std::string part = trim(raw);
    if (part.empty()) continue;  // "a=1;" and "a=1;;b=2" are harmless
    const std::string where = "--grid part '" + part + "'";
    const auto eq = part.find('=');
    if (eq == std::string::npos)
      throw GridError(where + ": expected Section.key=value1,value2,...");
    const std::string name = trim(part.substr(0, eq));
    const auto dot = name.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
      throw GridError(where + ": '" + name + "' is not of the form Section.key");
    SweptKey k;
    k.section = trim(name.substr(0, dot));
    k.key = trim(name.substr(dot + 1));
    for (const std::string& v : split(part.substr(eq + 1), ',')) {
      if (trim(v).empty()) throw GridError(where + ": empty value in the list");
      k.values.push_back(trim(v));
    }
    for (size_t i = 0; i < k.values.size(); ++i)
      if (std::count(k.values.begin(), k.values.end(), k.values[i]) > 1)
        throw GridError(where + ": value '" + k.values[i] + "' given twice");
    for (const auto& other : keys)
      if (other.name() == k.name()) throw GridError(where + ": " + k.name() + " swept twice");
    keys.push_back(std::move(k));
  }
  if (keys.empty()) throw GridError("--grid '" + text + "' names no key");
  return keys;
}

std::vector<Combination> combinations(const std::vector<SweptKey>& keys) {
  std::vector<Combination> all{Combination{std::vector<size_t>(keys.size(), 0)}};
  for (size_t k = keys.size(); k-- > 0;) {  // expand the first key last: it varies slowest
    std::vector<Combination> grown;
    for (size_t v = 0; v < keys[k].values.size(); ++v)
      for (Combination c : all) {
        c.value_index[k] = v;
        grown.push_back(c);
      }
    all = std::move(grown);
  }
  return all;
}

std::vector<std::string> overridesOf(const std::vector<SweptKey>& keys, const Combination& c) {
  std::vector<std::string> sets;
  for (size_t k = 0; k < keys.size(); ++k)
    sets.push_back(keys[k].name() + "=" + keys[k].values[c.value_index[k]]);
  return sets;
}

}  // namespace dynslam::sweep
