#include "gpu/gpu_board_renderer.hpp"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QVector3D>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/gl_helpers.hpp"
#include "gpu/knot_tables.hpp"
#include "gpu/wood_program.hpp"
#include "params/parameter_schema.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/resource_usage.hpp"

namespace kerf {
namespace {

// Texture units: the log's tables first (KnotTables), then the per-tile (first, count) ranges.
constexpr int kTilesUnit = KnotTables::kTextureCount;

}  // namespace

GpuBoardRenderer::GpuBoardRenderer() : program_(std::make_unique<QOpenGLShaderProgram>()) {
  const QString vertex = "#version 330 core\n" + WoodProgram::shaderFile("image_plane.vert");
  const QString fragment =
      "#version 330 core\n" + WoodProgram::parameterDeclarations() +
      WoodProgram::shaderFile("kernels/noise.glsl") + WoodProgram::shaderFile("kernels/knot_checks.glsl") +
      WoodProgram::shaderFile("knot_death.glsl") + WoodProgram::shaderFile("knots.glsl") + "\n#line 1 1\n" +
      WoodProgram::shaderFile("board_knots.frag");
  if (!program_->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
      !program_->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program_->link()) {
    throw std::runtime_error("knot shader failed to build: " + program_->log().toStdString());
  }
  currentGl()->glGenVertexArrays(1, &vertexArray_);
  currentGl()->glGenTextures(1, &tilesTexture_);
  tables_ = std::make_unique<KnotTables>();
}

GpuBoardRenderer::~GpuBoardRenderer() {
  if (QOpenGLContext::currentContext()) {
    currentGl()->glDeleteTextures(1, &tilesTexture_);
    currentGl()->glDeleteVertexArrays(1, &vertexArray_);
  }
}

Image GpuBoardRenderer::render(const KnotField& field, const WoodColorMap& colors, const Board& board,
                               const BoardRenderOptions& options, BoardRenderStats* stats,
                               GpuBoardTimings* timings) {
  GpuBoardTimings time;
  Stopwatch watch;
  // The pixel -> log mapping and the culling exactly as core's renderBoardFace.
  const BoardFaceLayout layout = layoutBoardFace(field, board, options);
  const glm::ivec2 size = layout.size;
  const std::vector<int>& boardKnots = layout.boardKnots;
  const int boardCount = static_cast<int>(boardKnots.size());

  // Per tile: (first, count) into one list of board-knot indices (0..boardCount-1, ascending).
  const int tilesX = layout.tilesX, tilesY = layout.tilesY;
  std::vector<std::vector<int>> rowLists(tilesY);
  std::vector<GLint> tileRanges(static_cast<std::size_t>(tilesX) * tilesY * 2);
  std::vector<int> boardIndex(field.log().knots.size(), -1);
  for (int i = 0; i < boardCount; ++i) boardIndex[boardKnots[i]] = i;
  parallelRows(tilesY, [&](int ty) {
    std::vector<int> tileKnots;
    std::vector<int>& list = rowLists[ty];
    for (int tx = 0; tx < tilesX; ++tx) {
      GLint* range = &tileRanges[(static_cast<std::size_t>(ty) * tilesX + tx) * 2];
      range[0] = static_cast<GLint>(list.size());  // made global below
      layout.tileKnots(field, tx, ty, tileKnots);
      for (const int k : tileKnots) list.push_back(boardIndex[k]);
      range[1] = static_cast<GLint>(tileKnots.size());
    }
  });
  std::vector<GLint> tileList;
  long long tileKnotSum = 0;
  for (int ty = 0; ty < tilesY; ++ty) {
    const auto first = static_cast<GLint>(tileList.size());
    for (int tx = 0; tx < tilesX; ++tx) {
      tileRanges[(static_cast<std::size_t>(ty) * tilesX + tx) * 2] += first;
      tileKnotSum += tileRanges[(static_cast<std::size_t>(ty) * tilesX + tx) * 2 + 1];
    }
    tileList.insert(tileList.end(), rowLists[ty].begin(), rowLists[ty].end());
  }
  time.cull = watch.seconds();
  watch = Stopwatch();

  // The framebuffer first: creating it binds its texture to the active unit, which would replace a table.
  QOpenGLFramebufferObjectFormat format;
  format.setInternalTextureFormat(0x8814);  // GL_RGBA32F: no 8-bit rounding before the comparison
  QOpenGLFramebufferObject fbo(size.x, size.y, format);
  if (!fbo.isValid() || !fbo.bind()) throw std::runtime_error("cannot create a float framebuffer");
  QOpenGLExtraFunctions* f = currentGl();
  // Tables: the stem, the board's knots (skeletons, death, noise), the colour map, the tile lists.
  tables_->uploadLog(field, colors, boardKnots, kTilesUnit);
  tables_->uploadKnotList(std::move(tileList), kTilesUnit);
  uploadTexelTable(tilesTexture_, kTilesUnit, GL_RG32I, tilesX, tilesY, GL_RG_INTEGER, GL_INT,
                   tileRanges.data());

  f->glViewport(0, 0, size.x, size.y);
  f->glDisable(GL_BLEND);
  f->glDisable(GL_DEPTH_TEST);
  QOpenGLShaderProgram& p = *program_;
  p.bind();
  tables_->bind(p, 0);
  p.setUniformValue("u_tiles", kTilesUnit);
  p.setUniformValue("u_origin", toQt(layout.origin));
  p.setUniformValue("u_stepX", toQt(layout.stepX));
  p.setUniformValue("u_stepY", toQt(layout.stepY));
  p.setUniformValue("u_imageHeight", static_cast<float>(size.y));
  p.setUniformValue("u_tileSize", layout.tile);
  time.upload = watch.seconds();
  watch = Stopwatch();

  f->glBindVertexArray(vertexArray_);
  f->glDrawArrays(GL_TRIANGLES, 0, 3);
  f->glFinish();
  time.draw = watch.seconds();
  watch = Stopwatch();

  std::vector<float> rgba(static_cast<std::size_t>(size.x) * size.y * 4);
  f->glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, rgba.data());
  fbo.release();
  p.release();
  Image image(size.x, size.y, 3);
  double inReach = 0;
  for (int y = 0; y < size.y; ++y) {  // OpenGL rows are bottom-up
    for (int x = 0; x < size.x; ++x) {
      const float* px = &rgba[(static_cast<std::size_t>(size.y - 1 - y) * size.x + x) * 4];
      std::copy_n(px, 3, image.pixel(x, y));
      inReach += px[3];
    }
  }
  time.readback = watch.seconds();
  if (stats) {
    stats->boardKnots = boardCount;
    stats->pixels = static_cast<std::size_t>(size.x) * size.y;
    stats->meanTileKnots = static_cast<double>(tileKnotSum) / (static_cast<double>(tilesX) * tilesY);
    stats->meanKnotsInReach = inReach / static_cast<double>(stats->pixels);
  }
  if (timings) *timings = time;
  return image;
}

}  // namespace kerf
