// docs/programs.md against the programs themselves: every program CMake builds and every script
// has a section; each answers --help and -h with exit code 0 and the same text on stdout; the
// flags its help lists (at the start of an option line) are exactly the flags the first column
// of its section's `flag` table lists. bag2rawlog only when it was built.
#include <dynslam/testing/TestEnv.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace dt = dynslam::testing;
namespace fs = std::filesystem;

namespace {

using Flags = std::set<std::string>;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

/// The flags written in `text`: words "--name" (cut at the first character a flag name does not
/// hold) and "-h", ignoring the quotes, commas and brackets around them.
Flags flagsIn(const std::string& text) {
  Flags flags;
  std::istringstream in(text);
  for (std::string word; in >> word;) {
    const auto b = word.find_first_not_of("`,;()[]");
    if (b == std::string::npos) continue;
    word = word.substr(b, word.find_last_not_of("`,;()[]") - b + 1);
    if (word == "-h") flags.insert(word);
    if (word.rfind("--", 0) != 0 || word.size() < 3) continue;
    const auto end = word.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-", 2);
    flags.insert(word.substr(0, end));
  }
  return flags;
}

/// A markdown table row's first cell ("\|" is a '|' inside it).
std::string firstCell(const std::string& row) {
  std::string cell;
  for (size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size()) {
      cell += row[++i];
      continue;
    }
    if (row[i] == '|') break;
    cell += row[i];
  }
  return cell;
}

/// docs/programs.md: per "## `name`" section, the flags of its tables headed "flag".
std::map<std::string, Flags> documentedFlags(const std::string& page) {
  std::map<std::string, Flags> sections;
  const std::regex heading("^## `([^`]+)`\\s*$");
  std::string section;
  bool inFlagTable = false, previousWasRow = false;
  for (const auto& line : lines(page)) {
    std::smatch m;
    if (std::regex_match(line, m, heading)) {
      section = m[1].str();
      sections[section];
    } else if (line.rfind("## ", 0) == 0) {
      section.clear();
    }
    const bool row = !line.empty() && line[0] == '|';
    if (row && !previousWasRow) {  // a table's header
      std::string header = firstCell(line);
      header.erase(0, header.find_first_not_of(' '));
      inFlagTable = header.rfind("flag", 0) == 0 && (header.size() == 4 || header[4] == ' ');
    } else if (row && inFlagTable && !section.empty() && line.rfind("|---", 0) != 0) {
      const Flags cell = flagsIn(firstCell(line));
      sections[section].insert(cell.begin(), cell.end());
    }
    previousWasRow = row;
  }
  return sections;
}

/// The flags a help text lists: those at the start of an option line (its first non-blank
/// character a '-'), in the option's column (up to the first two blanks).
Flags helpFlags(const std::string& help) {
  Flags flags;
  for (const auto& line : lines(help)) {
    const auto start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] != '-') continue;
    const auto gap = line.find("  ", start);
    const Flags column =
        flagsIn(line.substr(start, gap == std::string::npos ? std::string::npos : gap - start));
    flags.insert(column.begin(), column.end());
  }
  return flags;
}

/// The programs CMake builds (dynslam_add_program) and the scripts one runs (scripts/*.sh,
/// bench/*.sh and bench/paper_tables with a #! line; a sourced library has none).
std::set<std::string> programsAndScripts() {
  std::set<std::string> names;
  const std::regex program("dynslam_add_program\\(\\s*([A-Za-z0-9_-]+)");
  const fs::path root = dt::sourceDir();
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
       ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name[0] == '.')) {
      it.disable_recursion_pending();  // build trees and hidden folders hold no sources
      continue;
    }
    if (name != "CMakeLists.txt") continue;
    const std::string text = dt::readTextFile(it->path().string());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), program);
         it != std::sregex_iterator(); ++it)
      names.insert((*it)[1].str());
  }
  for (const char* folder : {"scripts", "bench"})
    for (const auto& entry : fs::directory_iterator(root / folder)) {
      const std::string name = entry.path().filename().string();
      const bool script = name.size() > 3 && name.substr(name.size() - 3) == ".sh";
      if (!entry.is_regular_file() || !(script || name == "paper_tables")) continue;
      if (dt::readTextFile(entry.path().string()).rfind("#!", 0) == 0)
        names.insert(std::string(folder) + "/" + name);
    }
  return names;
}

std::string joined(const Flags& flags) {
  std::string s;
  for (const auto& f : flags) s += (s.empty() ? "" : " ") + f;
  return s.empty() ? "(none)" : s;
}

/// `name --help` (or -h), stdout only: scripts through bash from the source tree, programs from
/// build/bin. nullopt when the program was not built.
std::optional<dt::CommandResult> help(const std::string& name, const char* flag) {
  std::string command;
  if (name.find('/') != std::string::npos) {
    command = "bash '" + dt::sourceDir() + "/" + name + "' " + flag;
  } else {
    const std::string path = dt::binDir() + "/" + name;
    if (!fs::exists(path)) return std::nullopt;
    command = "'" + path + "' " + flag;
  }
  return dt::runCommand("(" + command + " 2>/dev/null)");
}

const std::string& page() {
  static const std::string text = dt::readTextFile(dt::sourceDir() + "/docs/programs.md");
  return text;
}

TEST(ProgramsDoc, EveryProgramAndScriptHasASectionAndNoOtherSectionIsThere) {
  ASSERT_FALSE(page().empty()) << "docs/programs.md is missing";
  const auto sections = documentedFlags(page());
  const auto programs = programsAndScripts();
  EXPECT_GE(programs.size(), 20u);
  for (const auto& p : programs)
    EXPECT_TRUE(sections.count(p)) << p << " has no \"## `" << p << "`\" section";
  for (const auto& [name, flags] : sections)
    EXPECT_TRUE(programs.count(name)) << "section " << name << " is neither a program nor a script";
}

TEST(ProgramsDoc, HelpAnswersWithExitZeroAndListsExactlyTheDocumentedFlags) {
  const auto sections = documentedFlags(page());
  ASSERT_FALSE(sections.empty());
  size_t checked = 0;
  for (const auto& [name, documented] : sections) {
    SCOPED_TRACE(name);
    const auto longHelp = help(name, "--help");
    if (!longHelp) {
      EXPECT_EQ(name, "bag2rawlog") << name << " was not built";
      continue;
    }
    EXPECT_EQ(longHelp->exit_code, 0);
    const auto shortHelp = help(name, "-h");
    EXPECT_EQ(shortHelp->exit_code, 0);
    EXPECT_EQ(shortHelp->output, longHelp->output) << "-h and --help differ";
    const Flags listed = helpFlags(longHelp->output);
    EXPECT_TRUE(listed.count("--help") && listed.count("-h")) << longHelp->output;
    Flags undocumented, unlisted;
    for (const auto& f : listed)
      if (!documented.count(f)) undocumented.insert(f);
    for (const auto& f : documented)
      if (!listed.count(f)) unlisted.insert(f);
    EXPECT_TRUE(undocumented.empty())
        << name << " --help lists flags docs/programs.md does not: " << joined(undocumented);
    EXPECT_TRUE(unlisted.empty())
        << "docs/programs.md lists flags " << name << " --help does not: " << joined(unlisted);
    ++checked;
  }
  EXPECT_GE(checked, 19u);
}

TEST(ProgramsDoc, FlagParsingReadsTablesAndOptionLines) {
  const auto sections = documentedFlags(
      "## `a`\n\n| flag | meaning |\n|---|---|\n| `--x N` | x |\n| `--fx F --fy F` | f |\n"
      "| `--m a\\|b` | m |\n| `-h`, `--help` | help |\n\n| column | value |\n|---|---|\n"
      "| `--not-a-flag` | in another table |\n\n## Notes\n\n| flag | meaning |\n|---|---|\n"
      "| `--outside` | not a program's |\n");
  ASSERT_EQ(sections.size(), 1u);
  EXPECT_EQ(joined(sections.at("a")), "--fx --fy --help --m --x -h");
  EXPECT_EQ(joined(helpFlags("usage: a [--x N]\n  --x N     x, like --y\n  -h, --help  help\n"
                             "text --z\n      --w-arg ARG\n                 meaning\n")),
            "--help --w-arg --x -h");
}

}  // namespace
