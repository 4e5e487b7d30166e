// Findings of the command-line fuzzer (fuzz/fuzz_cli_arguments.cpp, docs/reliability.md), kept as tests.
#include <gtest/gtest.h>

#include <limits>

#include "cli_app.hpp"
#include "number_option.hpp"

using namespace kerf;

// addNumber with only a lower bound of another type (an int 0 for a float option: veneer --start, board
// --across-knot) took FLT_MAX converted to that type as its upper bound: undefined behaviour at every
// kerf-cli start (UBSan: "3.40282e+38 is outside the range of representable values of type 'int'"), and
// in the Release build an upper bound of 2.1e9 that no one asked for.
TEST(CliArgumentRegressions, LowerBoundOnlyOptionTakesEveryLargerValueOfItsType) {
  CLI::App app;
  float start = -1.0f;
  cli::addNumber(&app, "--start", start, "", 0);
  EXPECT_NO_THROW(app.parse("--start 3e30"));
  EXPECT_EQ(start, 3e30f);
  EXPECT_THROW(app.parse("--start -1"), CLI::ValidationError);
  // The whole command line as kerf-cli builds it.
  const std::unique_ptr<cli::CliApp> kerfCli = cli::makeCliApp();
  EXPECT_NO_THROW(kerfCli->app.parse("render-panel random:1 --type veneer --start 3e9 --out v.png"));
}
