#pragma once
// Runs kerf-cli (quiet) with arguments through the shell and returns its exit code, its output (stdout
// and stderr together) and the peak memory of the run. `runAs`: a command that runs it (e.g. setpriv).
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace kerf::bad {

struct CliResult {
  int exitCode = -1;
  std::string output;
  long peakRssKiB = 0;  // the largest resident set of any kerf-cli run by this test so far
};

inline CliResult runCli(const std::string& arguments, const std::string& runAs = "") {
  CliResult result;
  FILE* pipe = ::popen((runAs + KERF_CLI + " -q " + arguments + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) result.output.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  rusage usage{};
  if (::getrusage(RUSAGE_CHILDREN, &usage) == 0) result.peakRssKiB = usage.ru_maxrss;
  return result;
}

}  // namespace kerf::bad
