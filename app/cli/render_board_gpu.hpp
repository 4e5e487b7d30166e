#pragma once
// render-board --gpu: the board rendered by the GLSL knot model (gpu/gpu_board_renderer.hpp) in an
// offscreen OpenGL 3.3 core context. Only built with the GUI (KERF_BUILD_GUI); kerf-cli's CPU path needs
// no display.
#include <string>

#include "render/board_renderer.hpp"

namespace kerf::cli {

struct GpuBoardReport {
  std::string renderer;  // GL_RENDERER
  double setup = 0;      // Qt, the OpenGL context and the program, s
  double render = 0;     // culling + upload + draw + readback, s
  double draw = 0;       // draw + glFinish, s (the first draw also JIT-compiles the shader on Mesa)
  double readback = 0;   // s
};

// Throws InputError with a clear message when no OpenGL 3.3 core context can be had (no display, ...).
Image renderBoardOnGpu(const KnotField& field, const WoodColorMap& colors, const Board& board,
                       const BoardRenderOptions& options, BoardRenderStats& stats, GpuBoardReport& report);

}  // namespace kerf::cli
