#pragma once
// kerf-cli's command line: the top-level options and every subcommand registered on one CLI11 app. Shared
// by main.cpp and the argument fuzzer (fuzz/fuzz_cli_arguments.cpp), so the fuzzer parses exactly what
// users type.
#include <CLI/CLI.hpp>
#include <memory>
#include <vector>

#include "command.hpp"

namespace kerf::cli {

struct CliApp {
  CLI::App app{"kerf-cli: Kerf's wood model, headless"};
  Context context;
  int threads = 0;
  std::vector<Command> commands;
};

// Builds the app. Throws std::logic_error when a numeric option was added without the number check
// (a bug: number_option.hpp).
std::unique_ptr<CliApp> makeCliApp();

// The subcommand that was parsed, or nullptr.
const Command* parsedCommand(const CliApp& cli);

}  // namespace kerf::cli
