#include "render_board_gpu.hpp"

#include <QGuiApplication>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "gpu/gpu_board_renderer.hpp"
#include "gpu/offscreen_gl_context.hpp"
#include "util/error.hpp"
#include "util/resource_usage.hpp"

namespace kerf::cli {

namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

const char* const kHint = "run under xvfb-run (or with DISPLAY set), or leave out --gpu for the CPU path";

}  // namespace

Image renderBoardOnGpu(const KnotField& field, const WoodColorMap& colors, const Board& board,
                       const BoardRenderOptions& options, BoardRenderStats& stats, GpuBoardReport& report) {
  // Qt aborts the process when its platform plugin finds no display: check first.
  const std::string platform = environment("QT_QPA_PLATFORM");
  const bool x11 = !environment("DISPLAY").empty(), wayland = !environment("WAYLAND_DISPLAY").empty();
  if ((platform.empty() && !x11 && !wayland) || (platform.rfind("xcb", 0) == 0 && !x11) ||
      (platform.rfind("wayland", 0) == 0 && !wayland)) {
    throw InputError(std::string("--gpu needs an OpenGL 3.3 context, and there is no display: ") + kHint);
  }
  const Stopwatch setupWatch;
  static int argc = 1;
  static char name[] = "kerf-cli";
  static char* argv[] = {name, nullptr};
  QGuiApplication app(argc, argv);
  OffscreenGlContext context;
  if (const std::string error = context.makeCurrent(); !error.empty()) {
    throw InputError("--gpu: " + error + ": " + kHint);
  }
  report.renderer = context.renderer();
  try {
    GpuBoardRenderer renderer;
    report.setup = setupWatch.seconds();
    GpuBoardTimings timings;
    Image image = renderer.render(field, colors, board, options, &stats, &timings);
    report.render = timings.cull + timings.upload + timings.draw + timings.readback;
    report.draw = timings.draw;
    report.readback = timings.readback;
    return image;  // the renderer is released while its context is still current
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(std::string("--gpu: ") + e.what());
  }
}

}  // namespace kerf::cli
