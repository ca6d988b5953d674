// dynslam-params: the parameter reference (docs/parameters.md), generated from the code.
#include "params/ParameterReference.h"

#include <dynslam/core/AtomicFile.h>
#include <dynslam/core/CommandLine.h>

#include <iostream>

namespace {
const char* kUsage = R"(usage: dynslam-params [--out FILE]
       dynslam-params -h | --help

Prints every ini key of the runner's sections, of every registered stage and of dynslam-sim's
scenario files, with its default, the values it accepts and its meaning, as markdown: the page
docs/parameters.md (the test ParameterReference fails when that file differs from what this
prints). Regenerate it with
  build/bin/dynslam-params --out docs/parameters.md

Options:
  --out FILE    write the page to FILE instead of stdout
  -h, --help    print this text and exit

Exit codes: 0 written, 1 FILE cannot be written, 2 usage.
)";
}  // namespace

int main(int argc, char** argv) {
  return dynslam::core::runProgram("dynslam-params", [&] {
    dynslam::core::CommandLine cl({"--out"}, {});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const std::string text = dynslam::params::toMarkdown(dynslam::params::collectParameters());
    if (!cl.has("--out")) {
      std::cout << text;
      return 0;
    }
    const std::string path = cl.required("--out");
    dynslam::core::writeFileAtomically(path, text);
    std::cerr << "dynslam-params: wrote " << path << "\n";
    return 0;
  });
}
