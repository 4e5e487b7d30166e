#pragma once
// kerf-cli's subcommands: each lives in its own file and registers itself on the CLI11 app with an
// add...Command() function returning what to run when it was chosen. main.cpp lists them.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "geometry/cut_plane.hpp"
#include "util/progress.hpp"
#include "util/resource_usage.hpp"

namespace kerf::cli {

// What every command shares: --stats, --quiet, and the count of model evaluations for throughput.
struct Context {
  bool stats = false;
  bool quiet = false;
  std::size_t samples = 0;    // model evaluations done (pixels/voxels x supersamples), for --stats
  Stopwatch stopwatch;        // started with the program
  Progress progress() const;  // a console percentage on stderr unless quiet
  void printStats(const std::string& command) const;
};

struct Command {
  CLI::App* subcommand;
  std::function<void(Context&)> run;  // throws InputError / Cancelled
};

Command addDemoCommand(CLI::App& app);
Command addRenderFacesCommand(CLI::App& app);
Command addRenderCutCommand(CLI::App& app);
Command addExportVolumeCommand(CLI::App& app);
Command addParamsCommand(CLI::App& app);
Command addDetectCommand(CLI::App& app);
Command addFitCommand(CLI::App& app);
Command addReconstructCommand(CLI::App& app);  // reconstruct_command.cpp
Command addAnnotationsCommand(CLI::App& app);
Command addRenderBoardCommand(CLI::App& app);
Command addRenderPanelCommand(CLI::App& app);  // render_panel_command.cpp
Command addRectifyCommand(CLI::App& app);
Command addTextureCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);  // export_command.cpp

// --plane px,py,pz,nx,ny,nz (render-cut, export). Throws InputError.
CutPlane parsePlane(const std::string& text);

}  // namespace kerf::cli
