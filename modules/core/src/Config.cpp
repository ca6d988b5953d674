#include "dynslam/core/Config.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/config/CLoadableOptions.h>

#include <dynslam/core/Options.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

namespace dynslam::core {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

}  // namespace

IniConfig::IniConfig(std::shared_ptr<mrpt::config::CConfigFileMemory> mem, std::string source)
    : mem_(std::move(mem)), source_(std::move(source)) {}

IniConfig IniConfig::fromFile(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw ConfigError("cannot read config file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  IniConfig cfg = fromText(text.str(), path);
  cfg.folder_ = std::filesystem::absolute(path).parent_path().string();
  for (const auto& o : overrides) cfg.applyOverride(o);
  return cfg;
}

IniConfig IniConfig::fromText(const std::string& text, const std::string& source) {
  return IniConfig(std::make_shared<mrpt::config::CConfigFileMemory>(text), source);
}

IniConfig IniConfig::fromMrpt(const mrpt::config::CConfigFileBase& ini, const std::string& source) {
  auto mem = std::make_shared<mrpt::config::CConfigFileMemory>();
  std::vector<std::string> sections, keys;
  ini.getAllSections(sections);
  for (const auto& section : sections) {
    ini.getAllKeys(section, keys);
    for (const auto& key : keys) mem->write(section, key, ini.read_string(section, key, ""));
  }
  return IniConfig(std::move(mem), source);
}

void IniConfig::applyOverride(const std::string& assignment) {
  const auto eq = assignment.find('=');
  const auto dot = assignment.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq)
    throw ConfigError("--set '" + assignment + "': expected section.key=value");
  const std::string section = trim(assignment.substr(0, dot));
  const std::string key = trim(assignment.substr(dot + 1, eq - dot - 1));
  mem_->write(section, key, trim(assignment.substr(eq + 1)));
}

const mrpt::config::CConfigFileBase& IniConfig::ini() const { return *mem_; }

std::vector<std::string> IniConfig::sections() const {
  std::vector<std::string> s;
  mem_->getAllSections(s);
  // simpleini reports the unnamed top-level section as "": not a section a user wrote.
  s.erase(std::remove(s.begin(), s.end(), std::string()), s.end());
  return s;
}

std::vector<std::string> IniConfig::keys(const std::string& section) const {
  std::vector<std::string> k;
  mem_->getAllKeys(section, k);
  for (auto& key : k) key = trim(key);
  return k;
}

std::vector<std::string> knownKeys(const mrpt::config::CLoadableOptions& options) {
  // saveToConfigFile writes every option with its current value, so it is the one list of
  // keys that cannot drift from what loadFromConfigFile reads (a test checks both agree).
  mrpt::config::CConfigFileMemory mem;
  options.saveToConfigFile(mem, "s");
  std::vector<std::string> keys;
  mem.getAllKeys("s", keys);
  for (auto& key : keys) key = trim(key);  // MRPT pads names to align the values
  return keys;
}

namespace {
thread_local OptionsObserver* t_optionsObserver = nullptr;
}  // namespace

OptionsObserver* setOptionsObserver(OptionsObserver* observer) {
  OptionsObserver* previous = t_optionsObserver;
  t_optionsObserver = observer;
  return previous;
}

namespace {

std::mutex g_lookupMutex;
std::map<std::string, std::string> g_lookups;  // path value -> where it was looked for

/// Takes each relative input path the section sets from the ini's folder when the working
/// directory has nothing of that name and the ini's folder has; notes both places otherwise.
class PathResolver : public OptionVisitor {
 public:
  PathResolver(const IniConfig& cfg, const std::string& section) : cfg_(cfg), section_(section) {}

  void key(const std::string&, double&, Range, const std::string&) override {}
  void key(const std::string&, int&, Range, const std::string&) override {}
  void key(const std::string&, bool&, const std::string&) override {}
  void key(const std::string&, std::string&, const std::string&) override {}
  void word(const std::string&, std::string&, const std::vector<std::string>&,
            const std::string&) override {}
  void path(const std::string& name, std::string& value, const std::string&) override {
    namespace fs = std::filesystem;
    if (value.empty() || fs::path(value).is_absolute() || fs::exists(value) ||
        !cfg_.ini().keyExists(section_, name))
      return;
    const fs::path besideIni = fs::path(cfg_.folder()) / value;
    if (!cfg_.folder().empty() && fs::exists(besideIni)) {
      value = besideIni.lexically_normal().string();
      return;
    }
    std::string places = (fs::current_path() / value).lexically_normal().string();
    if (!cfg_.folder().empty()) places += " and " + besideIni.lexically_normal().string();
    std::lock_guard<std::mutex> lock(g_lookupMutex);
    g_lookups[value] = " (looked for as " + places + ")";
  }

 private:
  const IniConfig& cfg_;
  const std::string& section_;
};

void resolvePaths(Options& options, const IniConfig& cfg, const std::string& section) {
  PathResolver resolver(cfg, section);
  options.describe(resolver);
}

}  // namespace

std::string pathLookup(const std::string& value) {
  std::lock_guard<std::mutex> lock(g_lookupMutex);
  const auto it = g_lookups.find(value);
  return it == g_lookups.end() ? "" : it->second;
}

void loadOptionsStrict(mrpt::config::CLoadableOptions& options, const IniConfig& cfg,
                       const std::string& section) {
  if (t_optionsObserver) t_optionsObserver->aboutToLoad(options, section);
  const auto known = knownKeys(options);
  for (const auto& key : cfg.keys(section)) {
    const bool found =
        std::any_of(known.begin(), known.end(), [&](const std::string& k) { return k == key; });
    if (!found)
      throw ConfigError("unknown key '" + key + "' in section [" + section + "] of " +
                        cfg.source() + "; known keys: " + joined(known));
  }
  try {
    options.loadFromConfigFile(cfg.ini(), section);
  } catch (const std::invalid_argument& e) {  // a value readOneOf / readBool / ... refused
    throw ConfigError("[" + section + "] in " + cfg.source() + ": " + e.what());
  }
  if (auto* described = dynamic_cast<Options*>(&options)) resolvePaths(*described, cfg, section);
  if (t_optionsObserver) t_optionsObserver->loaded(options, section);
}

std::string readOneOf(const mrpt::config::CConfigFileBase& c, const std::string& section,
                      const std::string& key, const std::string& current,
                      const std::vector<std::string>& allowed) {
  const std::string value = c.read_string(section, key, current);
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
  std::string list;
  for (size_t i = 0; i < allowed.size(); ++i)
    list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
  throw std::invalid_argument(key + " = '" + value + "': expected " + list);
}

bool readBool(const mrpt::config::CConfigFileBase& c, const std::string& section,
              const std::string& key, bool current) {
  const std::string read = readOneOf(c, section, key, current ? "true" : "false",
                                     {"true", "false", "1", "0", "yes", "no"});
  return read == "true" || read == "1" || read == "yes";
}

void rejectUnknownSections(const IniConfig& cfg, const std::vector<std::string>& known) {
  for (const auto& s : cfg.sections())
    if (std::find(known.begin(), known.end(), s) == known.end())
      throw ConfigError("unknown section [" + s + "] in " + cfg.source() +
                        " (no configured stage reads it); known sections: " + joined(known));
}

namespace {

template <typename T>
void writePadded(mrpt::config::CConfigFileBase& c, const std::string& section,
                 const std::string& key, const T& value, const std::string& comment) {
  c.write(section, key, value, mrpt::config::MRPT_SAVE_NAME_PADDING(),
          mrpt::config::MRPT_SAVE_VALUE_PADDING(), comment);
}

}  // namespace

void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              double value, const std::string& comment) {
  writePadded(c, section, key, value, comment);
}
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              int value, const std::string& comment) {
  writePadded(c, section, key, value, comment);
}
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              bool value, const std::string& comment) {
  writePadded(c, section, key, value, comment);
}
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              const std::string& value, const std::string& comment) {
  writePadded(c, section, key, value, comment);
}
void writeKey(mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key,
              const char* value, const std::string& comment) {
  writePadded(c, section, key, std::string(value), comment);
}

}  // namespace dynslam::core
