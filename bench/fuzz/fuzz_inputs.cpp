// bench-fuzz-inputs: mutates small valid inputs of every kind the programs read (rawlogs, inis,
// trajectory files, the converters' folders) and runs the program on each. Every case must end
// with exit 0, or exit 1 and a message naming its file; never a signal, a hang or more memory
// than the limit.
#include "ChildProcess.h"
#include "InputKinds.h"
#include "Mutator.h"

#include <dynslam/core/CommandLine.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
namespace fz = dynslam::bench::fuzz;

namespace {

const char* const kUsage =
    R"(usage: bench-fuzz-inputs [--seed S] [--cases N] [--kinds K,K] [--jobs J] [--out DIR]
                         [--bin DIR] [--timeout S] [--memory-mb M]
       bench-fuzz-inputs -h | --help

Builds a small valid sample of each input kind, checks that the program reading it succeeds,
then runs the program on N mutated copies per kind (bit flips, overwritten bytes, truncation,
repeated and swapped blocks, a size field made huge; for text also numbers made NaN, infinite
or enormous, lines deleted, repeated or swapped, stray bytes). Kinds and programs:
  rawlog       dynslam on a rawlog of RGB-D frames (images inside), IMU and a GGA fix
               (plain and gzip-compressed)
  ini          dynslam --max-frames 4 with every key of the pipeline's sections (--print-config)
  trajectory   dynslam-eval ape / rpe on TUM, KITTI and EuRoC files (--json, --plot)
  sevenscenes  sevenscenes2rawlog on a 7-Scenes folder (JPEG, PNG depth, poses, intrinsics)
  tum          tum2rawlog on a TUM RGB-D folder (lists, PNGs, accelerometer, ground truth)
A case passes when the program exits 0, or exits 1 with a message that names the case's
folder (the file it could not use); a signal, a hang, another exit code or an error that names
no file fails it. Failing cases are kept in DIR/KIND/case-N with repro.sh and mutation.txt.

Options:
  --seed S         seed of the mutations (default 1); case i of a kind is the same for any --jobs
  --cases N        cases per kind (default 200)
  --kinds K,K      some kinds only (default all)
  --jobs J         cases run at once (default 1)
  --out DIR        where cases are written (default /tmp/bench-fuzz-inputs-PID); passing ones
                   are deleted
  --bin DIR        folder of the programs (default: this program's folder)
  --timeout S      a case running longer is killed and run again alone; over it again, it
                   counts as a hang (default 10)
  --memory-mb M    the address-space limit of each run, MB (default 2048; 0: none, for
                   sanitizer builds, whose shadow memory needs terabytes of address space)
  -h, --help       print this text and exit

Output: one line per kind (cases, exits 0 / 1, signals, hangs, other exits, errors naming no
file, the slowest case, the largest peak RSS), then the failing cases. Exit codes: 0 every
case passed, 1 a case failed or a sample did not pass unmutated, 2 usage.
)";

struct Outcome {
  std::string failure;  // "" when the case passed
  fz::ChildResult run;
  std::string what;  // the mutation
  std::string dir;
};

struct KindTally {
  size_t cases = 0, exit0 = 0, exit1 = 0, signals = 0, hangs = 0, otherExits = 0, unnamed = 0;
  size_t slowUnderLoad = 0;  // over the time limit among --jobs runs, within it alone
  double slowest = 0, peakRssMb = 0;
  std::vector<Outcome> failures;
};

std::string firstErrorLine(const std::string& output) {
  std::istringstream lines(output);
  std::string line, last;
  while (std::getline(lines, line)) {
    if (line.find("error") != std::string::npos) return line;
    if (!line.empty()) last = line;
  }
  return last;
}

/// The output names a file of the case (an input): paths into its out/ folder, which a run
/// prints anyway ("wrote .../out/summary.json"), do not count.
bool namesAnInput(std::string output, const std::string& dir) {
  const std::string outputs = dir + "/out";
  for (size_t at; (at = output.find(outputs)) != std::string::npos;)
    output.erase(at, outputs.size());
  return output.find(dir) != std::string::npos;
}

void writeFiles(const fz::InputKind& kind, const std::string& dir, const std::string& mutated,
                const std::string& bytes) {
  for (const auto& f : kind.files) {
    const fs::path path = fs::path(dir) / f.name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << (f.name == mutated ? bytes : f.bytes);
  }
  fs::create_directories(fs::path(dir) / "out");
}

std::string shellLine(const std::vector<std::string>& argv) {
  std::string line;
  for (const auto& a : argv) line += (line.empty() ? "'" : " '") + a + "'";
  return line;
}

/// Runs case `index` of `kind` (index -1: the unmutated sample) and classifies it.
Outcome runCase(const fz::InputKind& kind, size_t kindIndex, long index, uint64_t seed,
                const std::string& root, const fz::ChildLimits& limits) {
  std::vector<const fz::InputFile*> candidates;
  for (const auto& f : kind.files)
    if (f.mutated) candidates.push_back(&f);
  fz::Mutator mutator(seed * 1000003u + kindIndex * 7919u + uint64_t(index + 1));
  const fz::InputFile& target = *candidates[size_t(index + 1) % candidates.size()];
  Outcome o;
  fz::Mutation m{target.bytes, "none (the valid sample)"};
  if (index >= 0) m = mutator.mutate(target.bytes, target.text);
  o.what = target.name + ": " + m.what;
  o.dir = root + "/" + kind.name + "/case-" + (index < 0 ? "base" : std::to_string(index));
  fs::remove_all(o.dir);
  writeFiles(kind, o.dir, target.name, m.bytes);
  const auto argv = kind.command(o.dir, target.name);
  o.run = fz::runChild(argv, o.dir + "/output.txt", limits);
  if (o.run.timed_out)
    o.failure = "hang";
  else if (o.run.signal)
    o.failure = "signal " + std::to_string(o.run.signal);
  else if (o.run.exit_code != 0 && o.run.exit_code != 1)
    o.failure = "exit " + std::to_string(o.run.exit_code);
  else if (o.run.exit_code == 1 && !namesAnInput(o.run.output, o.dir))
    o.failure = "error naming no file";
  if (o.failure.empty()) {
    fs::remove_all(o.dir);
  } else {
    std::ofstream(o.dir + "/repro.sh") << "#!/bin/sh\n" << shellLine(argv) << "\n";
    std::ofstream(o.dir + "/mutation.txt") << o.what << "\n";
  }
  return o;
}

void count(KindTally& t, Outcome o) {
  ++t.cases;
  t.slowest = std::max(t.slowest, o.run.seconds);
  t.peakRssMb = std::max(t.peakRssMb, o.run.max_rss_mb);
  if (o.run.timed_out)
    ++t.hangs;
  else if (o.run.signal)
    ++t.signals;
  else if (o.run.exit_code == 0)
    ++t.exit0;
  else if (o.run.exit_code == 1)
    ++t.exit1;
  else
    ++t.otherExits;
  if (o.failure == "error naming no file") ++t.unnamed;
  if (!o.failure.empty()) t.failures.push_back(std::move(o));
}

KindTally fuzzKind(const fz::InputKind& kind, size_t kindIndex, size_t cases, uint64_t seed,
                   size_t jobs, const std::string& root, const fz::ChildLimits& limits) {
  std::vector<Outcome> outcomes(cases);
  std::atomic<size_t> next{0};
  std::vector<std::thread> workers;
  for (size_t j = 0; j < std::max<size_t>(1, jobs); ++j)
    workers.emplace_back([&] {
      for (size_t i; (i = next++) < cases;)
        outcomes[i] = runCase(kind, kindIndex, long(i), seed, root, limits);
    });
  for (auto& w : workers) w.join();
  KindTally tally;
  for (size_t i = 0; i < cases; ++i) {
    // The limit is wall time: among --jobs runs on a loaded machine a case can overrun it
    // without hanging. It runs again alone; a hang hangs again.
    if (outcomes[i].failure == "hang") {
      outcomes[i] = runCase(kind, kindIndex, long(i), seed, root, limits);
      tally.slowUnderLoad += outcomes[i].failure.empty();
    }
    count(tally, std::move(outcomes[i]));
  }
  return tally;
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> parts;
  std::istringstream in(s);
  for (std::string part; std::getline(in, part, ',');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace dynslam;
  return core::runProgram("bench-fuzz-inputs", [&] {
    core::CommandLine cl(
        {"--seed", "--cases", "--kinds", "--jobs", "--out", "--bin", "--timeout", "--memory-mb"},
        {});
    cl.parse(argc, argv);
    if (cl.helpRequested()) {
      std::cout << kUsage;
      return 0;
    }
    const uint64_t seed = uint64_t(cl.optionalInteger("--seed").value_or(1));
    const size_t cases = size_t(cl.optionalInteger("--cases").value_or(200));
    const size_t jobs = size_t(cl.optionalInteger("--jobs").value_or(1));
    fz::ChildLimits limits;
    limits.seconds = cl.optionalDouble("--timeout").value_or(10);
    limits.memory_mb = cl.optionalDouble("--memory-mb").value_or(2048);
    const std::string bin =
        cl.valueOr("--bin", fs::read_symlink("/proc/self/exe").parent_path().string());
    const std::string root =
        fs::absolute(cl.valueOr("--out", "/tmp/bench-fuzz-inputs-" + std::to_string(::getpid())))
            .string();
    const auto kinds = fz::makeInputKinds(bin, splitCommas(cl.valueOr("--kinds", "")));
    if (kinds.empty()) throw core::UsageError("--kinds: no known kind given");
    std::printf(
        "bench-fuzz-inputs: seed %llu, %zu cases per kind, limits %.0f s and %.0f MB, "
        "cases in %s\n",
        static_cast<unsigned long long>(seed), cases, limits.seconds, limits.memory_mb,
        root.c_str());
    bool failed = false;
    size_t total = 0, totalFailures = 0;
    for (size_t k = 0; k < kinds.size(); ++k) {
      const Outcome base = runCase(kinds[k], k, -1, seed, root, limits);
      if (base.run.exit_code != 0 || base.run.timed_out || base.run.signal) {
        std::printf("%-12s the valid sample failed (%s): %s\n", kinds[k].name.c_str(),
                    base.dir.c_str(), firstErrorLine(base.run.output).c_str());
        failed = true;
        continue;
      }
      const KindTally t = fuzzKind(kinds[k], k, cases, seed, jobs, root, limits);
      std::printf(
          "%-12s %zu cases: exit 0 %zu, exit 1 %zu; signals %zu, hangs %zu, other exits "
          "%zu, errors naming no file %zu; slowest %.2f s, peak RSS %.0f MB\n",
          kinds[k].name.c_str(), t.cases, t.exit0, t.exit1, t.signals, t.hangs, t.otherExits,
          t.unnamed, t.slowest, t.peakRssMb);
      for (const auto& f : t.failures)
        std::printf("  FAIL %s: %s (%s)\n    %s\n", f.dir.c_str(), f.failure.c_str(),
                    f.what.c_str(), firstErrorLine(f.run.output).c_str());
      std::fflush(stdout);  // a long run shows each kind as it ends
      total += t.cases;
      totalFailures += t.failures.size();
      failed = failed || !t.failures.empty();
    }
    std::printf("bench-fuzz-inputs: %zu cases, %zu failed\n", total, totalFailures);
    std::fflush(stdout);
    if (!failed) fs::remove_all(root);
    return failed ? 1 : 0;
  });
}
