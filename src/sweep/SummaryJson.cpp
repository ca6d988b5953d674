#include "sweep/SummaryJson.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dynslam::sweep {
namespace {

class Scanner {
 public:
  explicit Scanner(const std::string& text) : s_(text) {}

  bool parseTopLevel(std::map<std::string, std::string>& members) {
    if (!consume('{')) return false;
    if (consume('}')) return true;
    do {
      std::string key, value;
      if (!string(key) || !consume(':')) return false;
      skipSpace();
      if (peek() == '{' || peek() == '[') {
        if (!skipNested()) return false;
      } else if (peek() == '"') {
        if (!string(value)) return false;
        members[key] = value;
      } else {
        const size_t start = i_;
        while (i_ < s_.size() && s_[i_] != ',' && s_[i_] != '}' && !isSpace(s_[i_])) ++i_;
        if (i_ == start) return false;
        members[key] = s_.substr(start, i_ - start);
      }
    } while (consume(','));
    return consume('}');
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
  void skipSpace() {
    while (i_ < s_.size() && isSpace(s_[i_])) ++i_;
  }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  bool consume(char c) {
    skipSpace();
    if (peek() != c) return false;
    ++i_;
    return true;
  }
  bool string(std::string& out) {
    if (!consume('"')) return false;
    for (; i_ < s_.size(); ++i_) {
      const char c = s_[i_];
      if (c == '"') {
        ++i_;
        return true;
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      if (++i_ >= s_.size()) return false;
      switch (s_[i_]) {
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'u':  // only control characters are escaped this way by JsonWriter
          if (i_ + 4 >= s_.size()) return false;
          out += static_cast<char>(std::strtol(s_.substr(i_ + 1, 4).c_str(), nullptr, 16));
          i_ += 4;
          break;
        default:
          out += s_[i_];  // \" \\ \/
      }
    }
    return false;
  }
  bool skipNested() {
    int depth = 0;
    for (; i_ < s_.size(); ++i_) {
      const char c = s_[i_];
      if (c == '"') {
        std::string ignored;
        if (!string(ignored)) return false;
        --i_;
      } else if (c == '{' || c == '[') {
        ++depth;
      } else if (c == '}' || c == ']') {
        if (--depth == 0) {
          ++i_;
          return true;
        }
      }
    }
    return false;
  }

  const std::string& s_;
  size_t i_ = 0;
};

}  // namespace

std::string RunSummary::get(const std::string& key) const {
  const auto it = members.find(key);
  return it == members.end() ? std::string() : it->second;
}

std::optional<double> RunSummary::number(const std::string& key) const {
  const std::string text = get(key);
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

std::optional<RunSummary> readRunSummary(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  RunSummary summary;
  if (!Scanner(content).parseTopLevel(summary.members)) return std::nullopt;
  return summary;
}

bool jobCompleted(const std::string& dir) {
  const auto summary = readRunSummary(dir + "/summary.json");
  return summary && summary->get("status") == "ok";
}

}  // namespace dynslam::sweep
