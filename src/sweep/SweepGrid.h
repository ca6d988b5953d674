#pragma once
// The parameter grid of dynslam-sweep: "Section.key=v1,v2;Section.key2=a,b" -> every
// combination of values, each a list of `--set Section.key=value` overrides for dynslam.
#include <stdexcept>
#include <string>
#include <vector>

namespace dynslam::sweep {

struct GridError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// One swept ini key and the values it takes, in the order given.
struct SweptKey {
  std::string section;
  std::string key;
  std::vector<std::string> values;
  std::string name() const { return section + "." + key; }  ///< "Section.key"
};

/// Parses the --grid text; throws GridError quoting the part that is malformed (no '=', no
/// "section.key", an empty value, a key given twice).
std::vector<SweptKey> parseGrid(const std::string& text);

/// One point of the grid: value_index[k] indexes keys[k].values.
struct Combination {
  std::vector<size_t> value_index;
};

/// Every combination, the last key varying fastest.
std::vector<Combination> combinations(const std::vector<SweptKey>& keys);

/// The --set overrides of one combination: "Section.key=value" per key.
std::vector<std::string> overridesOf(const std::vector<SweptKey>& keys, const Combination& c);

}  // namespace dynslam::sweep
