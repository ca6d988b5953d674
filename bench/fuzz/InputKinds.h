#pragma once
// The kinds of input bench-fuzz-inputs mutates: a valid sample of each, built here (no
// download, no ../shared), and the program run that reads it.
#include <functional>
#include <string>
#include <vector>

namespace dynslam::bench::fuzz {

struct InputFile {
  std::string name;  ///< relative to the case's folder
  std::string bytes;
  bool text = false;
  bool mutated = true;  ///< a candidate for mutation (else written as is)
};

struct InputKind {
  std::string name;  ///< rawlog, ini, trajectory, sevenscenes, tum, bag
  std::vector<InputFile> files;
  /// The run on a case folder whose file `mutated` (a name of `files`) was changed.
  std::function<std::vector<std::string>(const std::string& caseDir, const std::string& mutated)>
      command;
};

/// Every kind, or those named in `only` (empty: all). `bin` is the folder of the programs
/// (dynslam, dynslam-eval, the converters). Kinds whose program was not built are left out,
/// with a line on stderr.
std::vector<InputKind> makeInputKinds(const std::string& bin, const std::vector<std::string>& only);

}  // namespace dynslam::bench::fuzz
