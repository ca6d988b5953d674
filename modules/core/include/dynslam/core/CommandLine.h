#pragma once
// The "--flag value" / "--switch" parser every program shares. Unknown flags, missing values,
// repeated flags (unless declared repeatable) and badly formed numbers are UsageErrors naming
// the flag: a typo that silently falls back to a default produces a wrong result.
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynslam::core {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class CommandLine {
 public:
  /// Flag names include the leading "--". valueFlags take a value ("--in DIR"), switches do
  /// not ("--embed-images"); repeatable value flags may be given several times ("--set").
  /// "--help" / "-h" is always accepted. maxPositional bounds the bare arguments.
  CommandLine(std::set<std::string> valueFlags, std::set<std::string> switches,
              std::set<std::string> repeatableFlags = {}, size_t maxPositional = 0);

  void parse(int argc, const char* const* argv);

  bool helpRequested() const { return help_; }
  bool has(const std::string& flag) const;
  /// The value of a flag that must be given; throws naming the flag when absent.
  std::string required(const std::string& flag) const;
  std::string valueOr(const std::string& flag, const std::string& fallback) const;
  /// Every value of a repeatable flag, in command-line order.
  std::vector<std::string> all(const std::string& flag) const;
  std::optional<double> optionalDouble(const std::string& flag) const;
  std::optional<long long> optionalInteger(const std::string& flag) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::set<std::string> valueFlags_, switches_, repeatable_;
  size_t maxPositional_;
  std::map<std::string, std::vector<std::string>> values_;
  std::vector<std::string> positional_;
  bool help_ = false;
};

/// An exception's message as a user should read it. MRPT's start with a "==== MRPT exception
/// ====" banner, then "Message:  ...", the location and a backtrace: of those only the message
/// line; any other message unchanged.
std::string userMessage(const std::string& what);

/// Runs a program body, printing "<program>: error: <what>" (userMessage) to stderr on an
/// exception and returning 2 for a UsageError, 1 for anything else; otherwise what the body
/// returned.
template <typename Body>
int runProgram(const char* program, Body&& body);

}  // namespace dynslam::core

#include <exception>
#include <iostream>

template <typename Body>
int dynslam::core::runProgram(const char* program, Body&& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    std::cerr << program << ": error: " << e.what() << " (see --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": error: " << userMessage(e.what()) << "\n";
    return 1;
  }
}
