// render-board: a board cut from a log, rendered with the knot model of Larsson et al. 2022 (docs/knots.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "field/knot_field.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"
#include "log_arguments.hpp"
#include "number_option.hpp"
#include "params/parameter_schema.hpp"
#include "render/board_renderer.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"
#ifdef KERF_CLI_GPU
#include "render_board_gpu.hpp"
#endif

namespace kerf::cli {

Command addRenderBoardCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("render-board", "Render a board cut from a log with knots (docs/knots.md)");
  struct Options {
    std::string log, out, board, face = "A", saveLog;
    std::vector<std::string> settings;
    int resolution = 1200, alongKnot = -1, acrossKnot = -1;
    float distance = -1.0f;
    bool noCull = false, gpu = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("LOG", o->log,
                  "A Kerf log file (.kerflog), a Gran_1 folder (JSON files, else image maps), or random:SEED")
      ->required();
  cmd->add_option("--out", o->out, "Output image (PNG, ...)")->required();
  cli::addNumber(cmd, "--res", o->resolution, "Pixels along the face's longer side", 1, 16384);
  cmd->add_option(
      "--board", o->board,
      "cx,cy,cz,sx,sy,sz[,rx,ry,rz]: centre (log mm), width,length,thickness (mm), rotations (deg); "
      "default: a flat-sawn board through the knottiest section");
  cmd->add_option("--face", o->face, "Which face of the board: A..F (A, the default, looks at the pith)")
      ->check(CLI::IsMember({"A", "B", "C", "D", "E", "F", "a", "b", "c", "d", "e", "f"}));
  cli::addNumber(cmd, "--along-knot", o->alongKnot,
                 "Instead of --board: face A along knot K's axis (radial plane)", 0);
  cli::addNumber(cmd, "--across-knot", o->acrossKnot,
                 "Instead of --board: face A across knot K, facing the pith", 0);
  cli::addNumber(
      cmd, "--distance", o->distance,
      "With --across-knot: distance of face A from the pith, mm (default: 25 mm past the knot's death, "
      "or 40 mm)");
  cmd->add_option("--set", o->settings, "Override a parameter: id=value (e.g. knots.butterfly=0.8)");
  cmd->add_option("--save-log", o->saveLog, "Also write the log in Kerf's log format");
  cmd->add_flag("--no-cull", o->noCull, "Evaluate every knot at every pixel (slow; for comparisons)");
  cmd->add_flag("--gpu", o->gpu,
                "Render with the GLSL knot model in an offscreen OpenGL 3.3 context (needs a display, e.g. "
                "xvfb-run)");
  return {cmd, [o](Context& context) {
            LogModel log = loadLogArgument(o->log);
            for (const std::string& file : {o->out, o->saveLog}) {
              const std::filesystem::path parent = std::filesystem::path(file).parent_path();
              if (!file.empty() && !parent.empty()) createOutputFolder(parent);
            }
            if (!o->saveLog.empty()) saveLogFile(log, o->saveLog);
            WoodParameters params;
            for (const std::string& s : o->settings) applySetting(params, s);
            Board board;
            if (o->alongKnot >= 0) {
              board = boardAlongKnot(log, o->alongKnot, {130.0f, 130.0f, 30.0f});
            } else if (o->acrossKnot >= 0) {
              if (o->acrossKnot >= static_cast<int>(log.knots.size())) {
                throw InputError("--across-knot: the log has " + std::to_string(log.knots.size()) + " knots");
              }
              const float death = log.knots[o->acrossKnot].deathDistance;
              const float distance =
                  o->distance > 0.0f ? o->distance : (std::isfinite(death) ? death + 25.0f : 40.0f);
              board = boardAcrossKnot(log, o->acrossKnot, distance, {60.0f, 60.0f, 20.0f});
            } else {
              board = o->board.empty() ? defaultBoard(log) : parseBoard(o->board);
            }
            if (!o->board.empty() && (o->alongKnot >= 0 || o->acrossKnot >= 0)) {
              throw InputError("--board cannot be combined with --along-knot or --across-knot");
            }
            const WoodColorMap colors = log.colorMap.empty()
                                            ? woodColorMapFromParameters(params, log.stem.maxRadius())
                                            : log.colorMap;
            const std::size_t knotCount = log.knots.size();
            const KnotField field(std::move(log), KnotSettings::fromParameters(params));
            BoardRenderOptions options;
            options.face = *faceFromLetter(o->face[0]);
            options.resolution = o->resolution;
            options.cull = !o->noCull;
            BoardRenderStats stats;
            const Stopwatch watch;
            std::string gpuReport;
            double gpuSeconds = -1.0;  // --gpu: the render alone, without starting Qt and OpenGL
            Image image;
            if (o->gpu) {
#ifdef KERF_CLI_GPU
              GpuBoardReport report;
              image = renderBoardOnGpu(field, colors, board, options, stats, report);
              char text[256];
              std::snprintf(text, sizeof text, " gpu=\"%s\" setup=%.3f s draw=%.3f s readback=%.3f s",
                            report.renderer.c_str(), report.setup, report.draw, report.readback);
              gpuReport = text;
              gpuSeconds = report.render;
#else
              throw InputError("--gpu: this kerf-cli was built without Qt/OpenGL (KERF_BUILD_GUI=OFF)");
#endif
            } else {
              image = renderBoardFace(field, colors, board, options, &stats, context.progress());
            }
            const double seconds = gpuSeconds >= 0.0 ? gpuSeconds : watch.seconds();
            writeImage(o->out, image);
            context.samples = stats.pixels;
            std::printf("board written to %s (%d x %d px, board %s, face %c)\n", o->out.c_str(), image.width,
                        image.height, formatBoard(board).c_str(), faceLetter(options.face));
            if (context.stats) {
              std::fprintf(
                  stderr,
                  "stats: render=%.3f s knots: log=%zu board=%d per-tile=%.2f per-pixel-in-reach=%.2f%s%s\n",
                  seconds, knotCount, stats.boardKnots, stats.meanTileKnots, stats.meanKnotsInReach,
                  options.cull ? "" : " (no culling)", gpuReport.c_str());
            }
          }};
}

}  // namespace kerf::cli
