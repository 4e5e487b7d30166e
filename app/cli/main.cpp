// kerf-cli: Kerf's core, headless, for batch work and tests. Every subcommand prints a clear message
// and exits non-zero on bad input; --stats prints timing, throughput and peak memory. Each subcommand
// lives in its own file (see command.hpp).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include "cli_app.hpp"
#include "io/output_guard.hpp"
#include "output_options.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace kerf;

int main(int argc, char** argv) {
  std::unique_ptr<cli::CliApp> cli;
  try {
    cli = cli::makeCliApp();
    cli->app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every mistake on the command line is bad input: exit code 2.
    return cli->app.exit(e) == 0 ? 0 : 2;
  } catch (const std::logic_error& e) {
    std::fprintf(stderr, "kerf-cli: internal error: %s\n", e.what());
    return 3;
  }
  setWorkerThreads(cli->threads);
  cli::Context& context = cli->context;

  // One command per run: an output that is one of its inputs is refused (io/output_guard.hpp).
  refuseOutputsOverInputs(true);
  try {
    if (const cli::Command* command = cli::parsedCommand(*cli)) {
      cli::checkOutputsAgainstInputs(*command->subcommand);
      command->run(context);
      context.printStats(command->subcommand->get_name());
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "kerf-cli: error: %s\n", e.what());
    return 2;
  } catch (const Cancelled&) {
    std::fprintf(stderr, "kerf-cli: cancelled\n");
    return 130;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "kerf-cli: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "kerf-cli: error: out of memory (is an input much larger than expected?)\n");
    return 3;
  } catch (const std::exception& e) {
    // A bug, not bad input: say so rather than abort with std::terminate's message.
    std::fprintf(stderr, "kerf-cli: internal error: %s (please report it with the input)\n", e.what());
    return 3;
  }
  return 0;
}
