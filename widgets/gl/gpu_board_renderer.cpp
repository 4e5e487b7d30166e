#include "gl/gpu_board_renderer.hpp"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QVector3D>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl_helpers.hpp"
#include "gl/wood_program.hpp"
#include "params/parameter_schema.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/resource_usage.hpp"

namespace kerf {
namespace {

constexpr int kRowLength = 4096;       // long 1D lists are wrapped into rows of this many texels
constexpr int kNoiseKnotsPerRow = 32;  // as in shaders/knots.glsl

enum Texture {
  kPith,
  kRadii,
  kKnotTables,
  kKnotInfo,
  kKnotNoise,
  kColors,
  kTiles,
  kTileKnots,
  kTextureCount
};

// A 2D texture read with texelFetch only: nearest, no mipmaps (so that it is complete).
void upload(unsigned texture, int unit, GLint internalFormat, int width, int height, GLenum format,
            GLenum type, const void* data) {
  QOpenGLExtraFunctions* f = currentGl();
  GLint maxSize = 0;
  f->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width > maxSize || height > maxSize) {
    throw std::runtime_error("board renderer: a " + std::to_string(width) + " x " + std::to_string(height) +
                             " table exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
  }
  f->glActiveTexture(GL_TEXTURE0 + unit);
  f->glBindTexture(GL_TEXTURE_2D, texture);
  f->glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  f->glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, data);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
}

// Pads a wrapped list to whole rows (at least one texel).
template <typename T>
int wrapRows(std::vector<T>& values, int componentsPerTexel) {
  const std::size_t texels = std::max<std::size_t>(values.size() / componentsPerTexel, 1);
  const int rows = static_cast<int>((texels + kRowLength - 1) / kRowLength);
  values.resize(static_cast<std::size_t>(rows) * kRowLength * componentsPerTexel, T{});
  return rows;
}

}  // namespace

GpuBoardRenderer::GpuBoardRenderer() : program_(std::make_unique<QOpenGLShaderProgram>()) {
  const QString vertex = "#version 330 core\n" + WoodProgram::shaderFile("image_plane.vert");
  const QString fragment = "#version 330 core\n" + QString::fromStdString(glslUniformDeclarations()) +
                           WoodProgram::shaderFile("knots.glsl") + "\n#line 1 1\n" +
                           WoodProgram::shaderFile("board_knots.frag");
  if (!program_->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
      !program_->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !program_->link()) {
    throw std::runtime_error("knot shader failed to build: " + program_->log().toStdString());
  }
  currentGl()->glGenVertexArrays(1, &vertexArray_);
  currentGl()->glGenTextures(kTextureCount, textures_);
}

GpuBoardRenderer::~GpuBoardRenderer() {
  if (QOpenGLContext::currentContext()) {
    currentGl()->glDeleteTextures(kTextureCount, textures_);
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

  // Tables: the stem, the board's knots (skeletons, death, noise), the colour map, the tile lists.
  const LogModel& log = field.log();
  const Stem& stem = log.stem;
  std::vector<float> pith(static_cast<std::size_t>(stem.slices()) * 2);
  for (int i = 0; i < stem.slices(); ++i) pith[2 * i] = stem.pith[i].x, pith[2 * i + 1] = stem.pith[i].y;
  int maxSamples = 1;
  for (const int k : boardKnots) maxSamples = std::max(maxSamples, log.knots[k].samples());
  const int knotRows = std::max(boardCount, 1);
  std::vector<float> tables(static_cast<std::size_t>(maxSamples) * knotRows * 2, 0.0f);
  std::vector<float> info(static_cast<std::size_t>(knotRows) * 4, 0.0f);
  constexpr int kAngles = KnotField::kNoiseTableAngles, kTimes = KnotField::kNoiseTableTimes;
  constexpr std::size_t kCells = static_cast<std::size_t>(kAngles) * kTimes;
  // The noise tables side by side, kNoiseKnotsPerRow knots of kAngles x kTimes per texture row.
  const int noiseRows = (knotRows + kNoiseKnotsPerRow - 1) / kNoiseKnotsPerRow;
  const std::size_t noiseWidth = static_cast<std::size_t>(kNoiseKnotsPerRow) * kAngles;
  std::vector<float> noise(noiseWidth * noiseRows * kTimes * 2, 0.0f);
  const std::vector<float>& speedNoise = field.speedNoiseTable();
  const std::vector<float>& outlineNoise = field.outlineNoiseTable();
  if (speedNoise.size() != kCells * log.knots.size() || outlineNoise.size() != speedNoise.size()) {
    throw std::logic_error("board renderer: unexpected knot noise table size");
  }
  for (int i = 0; i < boardCount; ++i) {
    const Knot& knot = log.knots[boardKnots[i]];
    for (int j = 0; j < knot.samples(); ++j) {
      tables[(static_cast<std::size_t>(i) * maxSamples + j) * 2] = knot.heights[j];
      tables[(static_cast<std::size_t>(i) * maxSamples + j) * 2 + 1] = knot.azimuths[j];
    }
    info[4 * i] = knot.distanceStep;
    info[4 * i + 1] = static_cast<float>(knot.samples());
    info[4 * i + 2] = knot.deathDistance;
    const std::size_t from = static_cast<std::size_t>(boardKnots[i]) * kCells;
    for (int t = 0; t < kTimes; ++t) {
      const std::size_t row = static_cast<std::size_t>(i / kNoiseKnotsPerRow) * kTimes + t;
      const std::size_t column = static_cast<std::size_t>(i % kNoiseKnotsPerRow) * kAngles;
      for (int a = 0; a < kAngles; ++a) {
        const std::size_t at = (row * noiseWidth + column + a) * 2;
        noise[at] = speedNoise[from + static_cast<std::size_t>(t) * kAngles + a];
        noise[at + 1] = outlineNoise[from + static_cast<std::size_t>(t) * kAngles + a];
      }
    }
  }
  std::vector<float> colorTexels;
  colorTexels.reserve(colors.colors.size() * 3);
  for (const glm::vec3& c : colors.colors) colorTexels.insert(colorTexels.end(), {c.x, c.y, c.z});
  const int colorRows = wrapRows(colorTexels, 3);
  const int listRows = wrapRows(tileList, 1);

  // The framebuffer first: creating it binds its texture to the active unit, which would replace a table.
  QOpenGLFramebufferObjectFormat format;
  format.setInternalTextureFormat(0x8814);  // GL_RGBA32F: no 8-bit rounding before the comparison
  QOpenGLFramebufferObject fbo(size.x, size.y, format);
  if (!fbo.isValid() || !fbo.bind()) throw std::runtime_error("cannot create a float framebuffer");
  QOpenGLExtraFunctions* f = currentGl();
  upload(textures_[kPith], kPith, GL_RG32F, stem.slices(), 1, GL_RG, GL_FLOAT, pith.data());
  upload(textures_[kRadii], kRadii, GL_R32F, stem.azimuths, stem.slices(), GL_RED, GL_FLOAT,
         stem.radii.data());
  upload(textures_[kKnotTables], kKnotTables, GL_RG32F, maxSamples, knotRows, GL_RG, GL_FLOAT, tables.data());
  upload(textures_[kKnotInfo], kKnotInfo, GL_RGBA32F, knotRows, 1, GL_RGBA, GL_FLOAT, info.data());
  upload(textures_[kKnotNoise], kKnotNoise, GL_RG32F, static_cast<int>(noiseWidth), kTimes * noiseRows, GL_RG,
         GL_FLOAT, noise.data());
  upload(textures_[kColors], kColors, GL_RGB32F, kRowLength, colorRows, GL_RGB, GL_FLOAT, colorTexels.data());
  upload(textures_[kTiles], kTiles, GL_RG32I, tilesX, tilesY, GL_RG_INTEGER, GL_INT, tileRanges.data());
  upload(textures_[kTileKnots], kTileKnots, GL_R32I, kRowLength, listRows, GL_RED_INTEGER, GL_INT,
         tileList.data());

  f->glViewport(0, 0, size.x, size.y);
  f->glDisable(GL_BLEND);
  f->glDisable(GL_DEPTH_TEST);
  QOpenGLShaderProgram& p = *program_;
  p.bind();
  const char* samplers[kTextureCount] = {"u_pith",      "u_radii",  "u_knotTables", "u_knotInfo",
                                         "u_knotNoise", "u_colors", "u_tiles",      "u_tileKnots"};
  for (int t = 0; t < kTextureCount; ++t) p.setUniformValue(samplers[t], t);
  p.setUniformValue("u_heightStep", stem.heightStep);
  p.setUniformValue("u_slices", stem.slices());
  p.setUniformValue("u_azimuths", stem.azimuths);
  p.setUniformValue("u_colorCount", static_cast<int>(colors.colors.size()));
  p.setUniformValue("u_colorRowLength", kRowLength);
  const KnotSettings& s = field.settings();
  p.setUniformValue("u_knotSpeed", s.speed);
  p.setUniformValue("u_knotSpeedDecline", s.speedDecline);
  p.setUniformValue("u_knotSpeedNoise", s.speedNoise);
  p.setUniformValue("u_knotSmoothStem", s.kStem);
  p.setUniformValue("u_knotSmoothKnot", s.kKnot);
  p.setUniformValue("u_knotSmoothTransition", s.kTransition);
  p.setUniformValue("u_knotReachStart", s.reachStart);
  p.setUniformValue("u_knotReachEnd", s.reachEnd);
  p.setUniformValue("u_knotDeadInversion", s.deadInversion);
  p.setUniformValue("u_knotDeadTransition", s.deadTransition);
  p.setUniformValue("u_knotDeadSharpening", s.deadSharpening);
  p.setUniformValue("u_knotButterfly", s.butterfly);
  p.setUniformValue("u_knotDarkening", toQt(s.darkening));
  p.setUniformValue("u_knotEdgeSoftness", s.edgeSoftness);
  p.setUniformValue("u_knotDeadDarkening", s.deadDarkening);
  p.setUniformValue("u_knotOutlineWidth", s.outlineWidth);
  p.setUniformValue("u_knotOutlineShade", s.outlineShade);
  p.setUniformValue("u_knotOutlineNoise", s.outlineNoise);
  p.setUniformValue("u_origin", toQt(layout.origin));
  p.setUniformValue("u_stepX", toQt(layout.stepX));
  p.setUniformValue("u_stepY", toQt(layout.stepY));
  p.setUniformValue("u_imageHeight", static_cast<float>(size.y));
  p.setUniformValue("u_tileSize", layout.tile);
  p.setUniformValue("u_tileListRow", kRowLength);
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
