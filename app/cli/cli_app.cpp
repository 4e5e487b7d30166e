#include "cli_app.hpp"

#include "number_option.hpp"

namespace kerf::cli {

std::unique_ptr<CliApp> makeCliApp() {
  auto cli = std::make_unique<CliApp>();
  CLI::App& app = cli->app;
  app.require_subcommand(1);
  app.add_flag("--stats", cli->context.stats,
               "Print wall time, threads, throughput and peak memory on stderr");
  addNumber(&app, "--threads", cli->threads, "Worker threads (0 = all cores)", 0, 256);
  app.add_flag("-q,--quiet", cli->context.quiet, "No progress output");
  cli->commands = {
      addDemoCommand(app),         addRenderFacesCommand(app), addRenderCutCommand(app),
      addExportVolumeCommand(app), addParamsCommand(app),      addDetectCommand(app),
      addFitCommand(app),          addReconstructCommand(app), addAnnotationsCommand(app),
      addRectifyCommand(app),      addRenderBoardCommand(app), addRenderPanelCommand(app),
      addTextureCommand(app),      addExportCommand(app),
  };
  requireCheckedNumbers(app);  // a numeric option added without the number check is a bug
  return cli;
}

const Command* parsedCommand(const CliApp& cli) {
  for (const Command& command : cli.commands)
    if (command.subcommand->parsed()) return &command;
  return nullptr;
}

}  // namespace kerf::cli
