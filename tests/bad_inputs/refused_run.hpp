#pragma once
// The check every "refused before the work" case shares (size limits, work budgets): kerf-cli exited
// with 2, printed its error matching `problem`, wrote nothing into `outDir`, and took little memory.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <regex>
#include <string>

#include "run_cli.hpp"

namespace kerf::bad {

// Far more than any refused request may take: the program and the parsed input, not the work.
inline constexpr long kMaxRefusedPeakKiB = 400 * 1024;

inline void expectRefusedAtOnce(const CliResult& r, const std::string& problem,
                                const std::filesystem::path& outDir) {
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("kerf-cli: error: "), std::string::npos) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(problem))) << r.output;
  // Linux counts the spawning process's own peak in the child's (exec keeps the old image's high-water
  // mark), so the bound is on top of this test's peak: small when ctest runs the test alone.
  rusage self{};
  ::getrusage(RUSAGE_SELF, &self);
  EXPECT_LT(r.peakRssKiB, self.ru_maxrss + kMaxRefusedPeakKiB)
      << "peak memory " << r.peakRssKiB / 1024 << " MiB (this test: " << self.ru_maxrss / 1024 << " MiB)";
  EXPECT_TRUE(std::filesystem::is_empty(outDir)) << "kerf-cli wrote output for a refused input";
}

}  // namespace kerf::bad
