#pragma once
// ini configuration the MRPT way (CConfigFileBase sections, CLoadableOptions structs), with the
// two rules this project adds: `--set section.key=value` overrides, and no silent typos (an
// unknown key or section is an error that names it).
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
class CConfigFileMemory;
class CLoadableOptions;
}  // namespace mrpt::config

namespace dynslam::core {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An ini held in memory, remembering where it came from for error messages.
class IniConfig {
 public:
  /// Reads `path` (error naming it when it cannot be read), then applies each override
  /// "section.key=value" in order.
  static IniConfig fromFile(const std::string& path,
                            const std::vector<std::string>& overrides = {});
  static IniConfig fromText(const std::string& text, const std::string& source = "<memory>");
  /// A copy of an MRPT config (an embedding program's CConfigFile, CConfigFileMemory, ...).
  static IniConfig fromMrpt(const mrpt::config::CConfigFileBase& ini,
                            const std::string& source = "<CConfigFileBase>");

  /// Applies one "section.key=value"; throws ConfigError when it is not of that form.
  void applyOverride(const std::string& assignment);

  const mrpt::config::CConfigFileBase& ini() const;
  const std::string& source() const { return source_; }
  /// The folder of the file it was read from ("" when it came from text): where the relative
  /// paths it sets are looked for when the working directory has none of that name.
  const std::string& folder() const { return folder_; }
  std::vector<std::string> sections() const;
  std::vector<std::string> keys(const std::string& section) const;

 private:
  IniConfig(std::shared_ptr<mrpt::config::CConfigFileMemory> mem, std::string source);
  std::shared_ptr<mrpt::config::CConfigFileMemory> mem_;
  std::string source_;
  std::string folder_;
};

/// Where an input path an ini set was looked for when it was found in neither place (" (looked
/// for as A and B)"), "" otherwise: for the error of whoever opens it.
std::string pathLookup(const std::string& value);

/// The keys an options struct knows: those its saveToConfigFile() writes.
std::vector<std::string> knownKeys(const mrpt::config::CLoadableOptions& options);

/// Loads `options` from `section` after checking that every key the section holds is one
/// `options` knows; otherwise throws ConfigError naming the key, the section and the source.
/// A relative input path (OptionVisitor::path) the section sets that does not exist from the
/// working directory but does from the ini's folder is taken from there.
/// A value the options refuse while loading (std::invalid_argument, e.g. from readBool or
/// readKeyword) becomes a ConfigError naming the section and the source too.
void loadOptionsStrict(mrpt::config::CLoadableOptions& options, const IniConfig& cfg,
                       const std::string& section);

/// Writes one documented key, `key = value // comment`, padded as MRPT's
/// MRPT_SAVE_CONFIG_VAR_COMMENT pads: what every saveToConfigFile() here does, and what the key
/// reference is generated from. One overload per value type keeps MRPT's headers out of this
/// file (a `const char*` value has its own, so it is never taken for a bool).
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              double value, const std::string& comment);
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              int value, const std::string& comment);
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              bool value, const std::string& comment);
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              const std::string& value, const std::string& comment);
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              const char* value, const std::string& comment);

/// An ini value that is one of a few words, each standing for an enum value (dynamic_handling =
/// none | remove | full, ...): one table per key serves reading, writing and the error.
template <class E>
struct Keyword {
  const char* word;
  E value;
};

/// Reads `key` of `section` as one of `allowed` (default: `current`); throws
/// std::invalid_argument "key = 'value': expected a, b or c" for any other word.
std::string readOneOf(const mrpt::config::CConfigFileBase& c, const std::string& section,
                      const std::string& key, const std::string& current,
                      const std::vector<std::string>& allowed);

/// Reads `key` of `section` as a boolean: true / false (also 1 / 0, yes / no; default:
/// `current`); throws std::invalid_argument "key = 'value': expected ..." for anything else
/// (MRPT's read_bool takes any other word for false).
bool readBool(const mrpt::config::CConfigFileBase& c, const std::string& section,
              const std::string& key, bool current);

/// The word of `value` in `words` (the first word when the value has none).
template <class E, std::size_t N>
const char* wordOf(E value, const Keyword<E> (&words)[N]) {
  for (const auto& w : words)
    if (w.value == value) return w.word;
  return words[0].word;
}

/// readOneOf with the words of `words`, returned as their enum value.
template <class E, std::size_t N>
E readKeyword(const mrpt::config::CConfigFileBase& c, const std::string& section,
              const std::string& key, E current, const Keyword<E> (&words)[N]) {
  std::vector<std::string> allowed;
  for (const auto& w : words) allowed.push_back(w.word);
  const std::string read = readOneOf(c, section, key, wordOf(current, words), allowed);
  for (const auto& w : words)
    if (read == w.word) return w.value;
  return current;  // not reached: readOneOf accepts only the listed words
}

/// Sees the options structs loadOptionsStrict loads, before it loads them (so they still hold
/// their defaults). The parameter reference (dynslam-params) configures every registered stage
/// once with one installed, so it learns each stage's sections, keys, defaults and comments
/// from the structs themselves instead of from a list that could drift.
/// `dynslam --print-config` installs one to see each struct once it is loaded.
class OptionsObserver {
 public:
  virtual ~OptionsObserver() = default;
  virtual void aboutToLoad(const mrpt::config::CLoadableOptions& options,
                           const std::string& section) {}
  /// After the values of `section` were read into `options` and accepted.
  virtual void loaded(const mrpt::config::CLoadableOptions& options, const std::string& section) {}
};

/// Installs `observer` for loadOptionsStrict calls made by the calling thread (nullptr: none);
/// returns the one it replaces.
OptionsObserver* setOptionsObserver(OptionsObserver* observer);

/// Throws ConfigError naming the first section of `cfg` that is not in `known`.
void rejectUnknownSections(const IniConfig& cfg, const std::vector<std::string>& known);

}  // namespace dynslam::core
