// kerf-cli: Kerf's core, headless, for batch work and tests. Every subcommand prints a clear message
// and exits non-zero on bad input; --stats prints timing, throughput and peak memory. Each subcommand
// lives in its own file (see command.hpp).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include "command.hpp"
#include "io/output_guard.hpp"
#include "number_option.hpp"
#include "output_options.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace kerf;

int main(int argc, char** argv) {
  CLI::App app{"kerf-cli: Kerf's wood model, headless"};
  app.require_subcommand(1);
  cli::Context context;
  int threads = 0;
  app.add_flag("--stats", context.stats, "Print wall time, threads, throughput and peak memory on stderr");
  cli::addNumber(&app, "--threads", threads, "Worker threads (0 = all cores)", 0, 256);
  app.add_flag("-q,--quiet", context.quiet, "No progress output");

  const std::vector<cli::Command> commands = {
      cli::addDemoCommand(app),         cli::addRenderFacesCommand(app), cli::addRenderCutCommand(app),
      cli::addExportVolumeCommand(app), cli::addParamsCommand(app),      cli::addDetectCommand(app),
      cli::addFitCommand(app),          cli::addReconstructCommand(app), cli::addAnnotationsCommand(app),
      cli::addRectifyCommand(app),      cli::addRenderBoardCommand(app), cli::addRenderPanelCommand(app),
      cli::addTextureCommand(app),      cli::addExportCommand(app),
  };

  try {
    cli::requireCheckedNumbers(app);  // a numeric option added without the number check is a bug
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every mistake on the command line is bad input: exit code 2.
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const std::logic_error& e) {
    std::fprintf(stderr, "kerf-cli: internal error: %s\n", e.what());
    return 3;
  }
  setWorkerThreads(threads);

  // One command per run: an output that is one of its inputs is refused (io/output_guard.hpp).
  refuseOutputsOverInputs(true);
  try {
    for (const cli::Command& command : commands) {
      if (!command.subcommand->parsed()) continue;
      cli::checkOutputsAgainstInputs(*command.subcommand);
      command.run(context);
      context.printStats(command.subcommand->get_name());
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
