#include "sweep/LocalRunner.h"

#include "sweep/SummaryJson.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>

extern char** environ;

namespace fs = std::filesystem;

namespace dynslam::sweep {
namespace {

using Clock = std::chrono::steady_clock;

std::atomic<bool> g_interrupted{false};
extern "C" void onSweepInterrupt(int) { g_interrupted = true; }

/// Starts argv with stdout and stderr appended to dir/dynslam.log; returns the pid.
pid_t spawn(const std::vector<std::string>& argv, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create the job folder '" + dir + "': " + ec.message());
  fs::remove(fs::path(dir) / "summary.json", ec);
  const std::string log = (fs::path(dir) / "dynslam.log").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error("cannot start '" + argv[0] + "': " + std::strerror(err));
  return pid;
}

/// Waits for any child; retries when a signal interrupts the wait.
pid_t waitAny(int& status) {
  for (;;) {
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid >= 0 || errno != EINTR) return pid;
  }
}

JobOutcome outcomeOf(int status, const std::string& dir, double seconds) {
  JobOutcome o;
  o.seconds = seconds;
  const auto summary = readRunSummary((fs::path(dir) / "summary.json").string());
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && summary && summary->get("status") == "ok") {
    o.ok = true;
    return o;
  }
  if (summary && !summary->get("error").empty())
    o.reason = summary->get("error");
  else if (summary && summary->get("status") == "interrupted")
    o.reason = "interrupted";
  else if (WIFSIGNALED(status))
    o.reason = std::string("killed by signal ") + strsignal(WTERMSIG(status));
  else if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    o.reason = "dynslam could not be started (see dynslam.log)";
  else
    o.reason = "exit code " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
               (summary ? "" : ", no summary.json");
  return o;
}

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

bool runLocally(const SweepSpec& spec, const std::vector<const Job*>& jobs, int parallel,
                const std::function<void(const Job&, const JobOutcome&)>& done) {
  struct Running {
    const Job* job;
    Clock::time_point start;
  };
  std::map<pid_t, Running> running;
  g_interrupted = false;
  auto previous = std::signal(SIGINT, onSweepInterrupt);
  size_t next = 0;
  try {
    while (next < jobs.size() || !running.empty()) {
      while (!g_interrupted && next < jobs.size() && static_cast<int>(running.size()) < parallel) {
        const Job* job = jobs[next++];
        running[spawn(dynslamArgv(spec, *job), job->dir)] = {job, Clock::now()};
      }
      if (running.empty()) break;  // interrupted before anything else started
      int status = 0;
      const pid_t pid = waitAny(status);
      if (pid < 0) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const Running r = it->second;
      running.erase(it);
      done(*r.job, outcomeOf(status, r.job->dir, since(r.start)));
    }
  } catch (...) {
    std::signal(SIGINT, previous);
    throw;
  }
  std::signal(SIGINT, previous);
  return !g_interrupted;
}

JobOutcome runOne(const std::vector<std::string>& argv, const std::string& dir) {
  const auto start = Clock::now();
  const pid_t pid = spawn(argv, dir);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return outcomeOf(status, dir, since(start));
}

}  // namespace dynslam::sweep
