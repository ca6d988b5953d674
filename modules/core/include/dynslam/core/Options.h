#pragma once
// Options declared once. An options struct lists its ini keys in describe(): for each key its
// name, the field that holds it (whose initializer is the default), the values it accepts and
// what it means; reading with range checks, writing, the strict unknown-key check and the
// parameter reference (docs/parameters.md) are all driven by that one list. A setting that acts
// only together with another says so there too (OptionVisitor::requires), and loading fails,
// naming both keys, when an ini sets it without the other.
//
//   void TrackingOptions::describe(core::OptionVisitor& v) {
//     v.key("rho_min", tracker.rho_min, core::Range::closedOpen(0, 1),
//           "accept a (track, detection) pair only if its depth IoU exceeds this");
//     v.key("mode", mode, kModeWords, "deterministic | realtime");
//     v.requires("identity_repair", tracker.identity_repair > 0,
//                "identity_check > 0", tracker.identity_check > 0);
//   }
#include <dynslam/core/Config.h>

#include <mrpt/config/CLoadableOptions.h>

#include <limits>
#include <string>
#include <vector>

namespace dynslam::core {

/// The values a numeric key accepts: an interval, either end closed, open or absent.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false, max_open = false;

  static Range any() { return {}; }
  static Range atLeast(double v) { return {v, any().max, false, false}; }      ///< [v, inf)
  static Range above(double v) { return {v, any().max, true, false}; }         ///< (v, inf)
  static Range closed(double a, double b) { return {a, b, false, false}; }     ///< [a, b]
  static Range closedOpen(double a, double b) { return {a, b, false, true}; }  ///< [a, b)

  bool contains(double v) const;
  /// "any", ">= 0", "> 0", "[0, 1]", "[0, 1)".
  std::string text() const;
};

/// Sees every key an options struct describes. Loading, writing, checking and documenting are
/// visitors; an options struct never knows which one it is talking to.
class OptionVisitor {
 public:
  virtual ~OptionVisitor() = default;

  virtual void key(const std::string& name, double& value, Range range,
                   const std::string& meaning) = 0;
  virtual void key(const std::string& name, int& value, Range range,
                   const std::string& meaning) = 0;
  /// true / false (also 1 / 0, yes / no when read).
  virtual void key(const std::string& name, bool& value, const std::string& meaning) = 0;
  /// Free text (a path, a label, a list).
  virtual void key(const std::string& name, std::string& value, const std::string& meaning) = 0;
  /// An input file or folder. Relative, it is looked for from the working directory, then from
  /// the folder of the ini that set it (loadOptionsStrict), so an ini's paths work from anywhere.
  virtual void path(const std::string& name, std::string& value, const std::string& meaning) {
    key(name, value, meaning);
  }
  /// One word of `words`.
  virtual void word(const std::string& name, std::string& value,
                    const std::vector<std::string>& words, const std::string& meaning) = 0;

  /// An enum read and written as one of the words of its Keyword table.
  template <class E, std::size_t N>
  void key(const std::string& name, E& value, const Keyword<E> (&words)[N],
           const std::string& meaning) {
    std::vector<std::string> allowed;
    for (const auto& w : words) allowed.push_back(w.word);
    std::string text = wordOf(value, words);
    word(name, text, allowed, meaning);
    for (const auto& w : words)
      if (text == w.word) value = w.value;
  }

  /// `name` acts only while `needed` holds: a loader refuses `name` set (`is_set`) by the
  /// section it reads while `needed` does not hold (`needed_holds`), naming both. Call it after
  /// both keys.
  virtual void requires(const std::string& name, bool is_set, const std::string& needed,
                        bool needed_holds) {
    (void)name, (void)is_set, (void)needed, (void)needed_holds;
  }
};

/// MRPT's CLoadableOptions (loadFromConfigFile / saveToConfigFile, so the struct works wherever
/// MRPT expects one) for a struct that lists its keys once, in describe().
class Options : public mrpt::config::CLoadableOptions {
 public:
  /// Lists every key (OptionVisitor). Const use (saving, documenting) leaves the fields as
  /// they are: those visitors only read.
  virtual void describe(OptionVisitor& v) = 0;

  /// Reads each listed key present in `section` (absent: the field keeps its value). Throws
  /// std::invalid_argument naming the key and the value for a value that is not a number, not
  /// in its range or not one of its words, and for a setting whose requirement does not hold;
  /// loadOptionsStrict adds the section and the file.
  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                          const std::string& section) override;
  /// Writes every key, `key = value // meaning`.
  void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                        const std::string& section) const override;

  /// Throws std::invalid_argument naming the first key whose current value is outside its
  /// range or whose requirement does not hold (for options set in code, not read).
  void check() const;
};

/// One key as the parameter reference shows it.
struct KeyDoc {
  std::string key;
  std::string default_value;  ///< the value before loading, as an ini would hold it
  std::string accepts;        ///< "[0, 1)", "a | b | c", "true | false", "" for free text
  std::string meaning;        ///< with "needs X" appended for a key that needs another
};

/// Every key `options` describes, with its current value as the default.
std::vector<KeyDoc> describeKeys(const Options& options);

/// "0.300000" -> "0.3": a double as an ini would hold it (%.10g).
std::string formatNumber(double value);

}  // namespace dynslam::core
