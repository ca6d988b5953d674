#include "tracking_run_set.h"

#include <dynslam/core/CommandLine.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <sstream>
#include <thread>

namespace dynslam::bench {

std::vector<int> parseRange(const std::string& flag, const std::string& text) {
  std::vector<int> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    int first = 0, last = 0;
    char extra = 0;
    if (std::sscanf(item.c_str(), "%d-%d%c", &first, &last, &extra) == 2 && first <= last) {
      for (int v = first; v <= last; ++v) values.push_back(v);
    } else if (std::sscanf(item.c_str(), "%d%c", &first, &extra) == 1) {
      values.push_back(first);
    } else {
      throw core::UsageError(flag + " must read A-B or A,B,... (integers), not '" + text + "'");
    }
  }
  if (values.empty()) throw core::UsageError(flag + " names no value");
  return values;
}

namespace {

struct RunResult {
  int scenario = 0, seed = 0;
  std::vector<RunScore> scores;  // one per configuration
};

void printTable(const std::vector<RunResult>& results,
                const std::vector<std::string>& configurations) {
  int width = 5;
  for (const auto& c : configurations) width = std::max(width, int(c.size()));
  std::printf("\nIDF1 per run (MOTA, ID switches in the summary below)\n  scenario  seed");
  for (const auto& c : configurations) std::printf("  %*s", width, c.c_str());
  std::printf("\n");
  for (const auto& r : results) {
    std::printf("  %8d  %4d", r.scenario, r.seed);
    for (const auto& score : r.scores) std::printf("  %*.3f", width, score.idf1);
    std::printf("\n");
  }
  std::printf("\nover %zu runs%s\n", results.size(),
              configurations.size() > 1 ? " (better / worse: IDF1 against the first column, "
                                          "by more than 0.001)"
                                        : "");
  for (size_t c = 0; c < configurations.size(); ++c) {
    double mota = 0, idf1 = 0, switches = 0;
    int atTarget = 0, better = 0, worse = 0;
    for (const auto& r : results) {
      const RunScore& score = r.scores[c];
      mota += score.mota;
      idf1 += score.idf1;
      switches += double(score.id_switches);
      atTarget += score.idf1 >= 0.90;
      better += score.idf1 > r.scores[0].idf1 + 1e-3;
      worse += score.idf1 < r.scores[0].idf1 - 1e-3;
    }
    const double n = double(std::max<size_t>(1, results.size()));
    std::printf("  %-*s  IDF1 %.4f (ratio to 0.90: %.2f), MOTA %.4f, ID switches %.1f, %d of %zu "
                "runs >= 0.90",
                width, configurations[c].c_str(), idf1 / n, idf1 / n / 0.90, mota / n, switches / n,
                atTarget, results.size());
    if (c > 0) std::printf("; %d better, %d worse", better, worse);
    std::printf("\n");
  }
}

}  // namespace

void benchRunSet(const BenchSettings& s, const std::vector<int>& scenarios,
                 const std::vector<int>& seeds, int jobs,
                 const std::vector<std::string>& configurations, const ScoreRun& score) {
  std::vector<RunResult> results;
  for (const int scenario : scenarios)
    for (const int seed : seeds) results.push_back({scenario, seed, {}});
  std::printf(
      "run set         %zu runs (%zu choreographies, Scenario.seed; %zu detector seeds), "
      "%d in parallel; %s, depth %s\n",
      results.size(), scenarios.size(), seeds.size(), jobs, s.config.c_str(),
      depthSource(s).c_str());
  std::fflush(stdout);
  std::atomic<size_t> next{0};
  std::mutex progress;
  size_t done = 0;
  std::exception_ptr failure;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (size_t i = next++; i < results.size(); i = next++) {
      RunResult& r = results[i];
      try {
        BenchSettings one = s;
        one.seed = uint32_t(r.seed);
        // Last wins: the choreography overrides a Scenario.seed given with --set.
        one.sim_overrides.push_back("Scenario.seed=" + std::to_string(r.scenario));
        r.scores = score(prepareSimulatedRun(one));
      } catch (...) {
        const std::lock_guard<std::mutex> lock(progress);
        if (!failure) failure = std::current_exception();
        next = results.size();
        return;
      }
      const std::lock_guard<std::mutex> lock(progress);
      std::fprintf(stderr, "[%zu/%zu] scenario %d seed %d: IDF1 %.3f (%.0f s)\n", ++done,
                   results.size(), r.scenario, r.seed, r.scores.front().idf1,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  };
  std::vector<std::thread> threads;
  for (int k = 0; k < std::max(1, jobs); ++k) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  printTable(results, configurations);
}

}  // namespace dynslam::bench
