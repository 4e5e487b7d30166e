#pragma once
// Runs kerf-cli (quiet) with arguments through the shell and returns its exit code, its output (stdout
// and stderr together) and the run's peak memory (wait4). `runAs`: a command that runs it (e.g. setpriv).
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>

extern char** environ;

namespace kerf::bad {

struct CliResult {
  int exitCode = -1;
  std::string output;
  long peakRssKiB = 0;  // ru_maxrss of the run (it includes the spawning process's peak, see the size tests)
};

inline CliResult runCli(const std::string& arguments, const std::string& runAs = "") {
  CliResult result;
  int out[2];
  if (::pipe(out) != 0) return result;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  const std::string command = "exec " + runAs + KERF_CLI + " -q " + arguments;
  const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
  pid_t pid = -1;
  const int spawned =
      ::posix_spawn(&pid, "/bin/sh", &actions, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (spawned != 0) {
    ::close(out[0]);
    return result;
  }
  char buffer[4096];
  for (ssize_t n; (n = ::read(out[0], buffer, sizeof buffer)) > 0;) result.output.append(buffer, n);
  ::close(out[0]);
  int status = 0;
  rusage usage{};
  if (::wait4(pid, &status, 0, &usage) != pid) return result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.peakRssKiB = usage.ru_maxrss;
  return result;
}

// Runs `command` with bash (e.g. "ulimit -f 4; kerf-cli ..."), returning its exit code and output.
inline CliResult runShell(const std::string& command) {
  CliResult result;
  FILE* pipe = ::popen(("bash -c '" + command + " 2>&1'").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) result.output.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

}  // namespace kerf::bad
