// Fuzz target: kerf-cli's command line (issue 21, "fuzz every CLI command's arguments"). An input becomes
// an argument vector for one subcommand, parsed in-process by the very app kerf-cli builds
// (app/cli/cli_app.hpp), then checked as main.cpp checks it before running (outputs against inputs). The
// command itself is not run: the heavy work is the file readers' fuzzers' business, and this target is
// after the parser, the number checks (cli/number_option.*), the list options and the output guard.
//
// Input layout: byte 0 picks the subcommand (every one is reachable); the rest is split at NUL bytes into
// arguments. An argument whose first byte is below 0x20 becomes that subcommand's option name number
// (byte % option count), and its remaining bytes, if any, a separate argument after it: so the fuzzer
// reaches every option without a dictionary, and still mutates raw text freely.
//
// The rule checked: parsing ends in success, a CLI11 parse error or an InputError; anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_app.hpp"
#include "output_options.hpp"
#include "util/error.hpp"

namespace {

std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::unique_ptr<kerf::cli::CliApp> cli = kerf::cli::makeCliApp();
  const kerf::cli::Command& chosen = cli->commands[data[0] % cli->commands.size()];
  const std::vector<std::string> names = optionNames(*chosen.subcommand);

  std::vector<std::string> arguments = {"kerf-cli", chosen.subcommand->get_name()};
  std::string token;
  const auto finish = [&] {
    if (!token.empty() && static_cast<unsigned char>(token[0]) < 0x20 && !names.empty()) {
      arguments.push_back(names[static_cast<unsigned char>(token[0]) % names.size()]);
      if (token.size() > 1) arguments.push_back(token.substr(1));
    } else {
      arguments.push_back(token);
    }
    token.clear();
  };
  for (std::size_t i = 1; i < size; ++i) {
    if (data[i] == 0)
      finish();
    else
      token.push_back(static_cast<char>(data[i]));
  }
  if (size > 1) finish();
  // Never --help: it prints the whole help text for every such input and proves nothing.
  for (const std::string& argument : arguments)
    if (argument == "-h" || argument == "--help") return 0;

  std::vector<const char*> argv;
  for (const std::string& argument : arguments) argv.push_back(argument.c_str());
  try {
    // CLI11 parses argv from the end (it takes them as a stack), as kerf-cli's main does.
    cli->app.parse(static_cast<int>(argv.size()), argv.data());
    const kerf::cli::Command* parsed = kerf::cli::parsedCommand(*cli);
    if (parsed == nullptr) {
      std::fprintf(stderr, "kerf fuzz: a parse succeeded without a subcommand\n");
      std::abort();
    }
    kerf::cli::checkOutputsAgainstInputs(*parsed->subcommand);
  } catch (const CLI::ParseError&) {
  } catch (const kerf::InputError&) {
  }
  return 0;
}
