#pragma once
// Boards cut from a log rendered on the GPU (shaders/knots.glsl, shaders/board_knots.frag): the GLSL twin
// of core's renderBoardFace (core/render/board_renderer.hpp), offscreen into a float framebuffer.
// Culling stays on the CPU: per board only the knots KnotField::cull keeps are uploaded, and per 16 x 16
// pixel tile a list of the knots that can reach the tile (the same boxes as core's renderer), so the
// fragment stage evaluates only those. Needs a current OpenGL 3.3 core context.
#include <memory>

#include "io/image.hpp"
#include "render/board_renderer.hpp"

class QOpenGLShaderProgram;

namespace kerf {

class KnotTables;

struct GpuBoardTimings {
  double cull = 0;      // per-board and per-tile culling on the CPU, s
  double upload = 0;    // textures and uniforms, s
  double draw = 0;      // draw + glFinish, s
  double readback = 0;  // glReadPixels and the conversion to an Image, s
};

class GpuBoardRenderer {
 public:
  GpuBoardRenderer();  // compiles the program; throws std::runtime_error
  ~GpuBoardRenderer();
  GpuBoardRenderer(const GpuBoardRenderer&) = delete;
  GpuBoardRenderer& operator=(const GpuBoardRenderer&) = delete;

  // As renderBoardFace: the face of `board` as an RGB image, `options.resolution` pixels along its longer
  // side. stats->meanKnotsInReach is counted by the shader.
  Image render(const KnotField& field, const WoodColorMap& colors, const Board& board,
               const BoardRenderOptions& options, BoardRenderStats* stats = nullptr,
               GpuBoardTimings* timings = nullptr);

 private:
  std::unique_ptr<QOpenGLShaderProgram> program_;
  std::unique_ptr<KnotTables> tables_;
  unsigned vertexArray_ = 0;
  unsigned tilesTexture_ = 0;  // RG32I, tilesX x tilesY: (first, count) into the knot list
};

}  // namespace kerf
