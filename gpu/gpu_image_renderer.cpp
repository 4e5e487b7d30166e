#include "gpu/gpu_image_renderer.hpp"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFramebufferObject>
#include <QVector3D>
#include <cmath>

#include "gpu/board_wood_textures.hpp"
#include "gpu/gl_helpers.hpp"
#include "gpu/wood_program.hpp"
#include "util/error.hpp"

namespace kerf {

GpuImageRenderer::GpuImageRenderer()
    : program_(std::make_unique<WoodProgram>("image_plane.vert", "image_plane.frag")) {
  currentGl()->glGenVertexArrays(1, &vertexArray_);  // core profile: drawing needs a bound VAO
}

GpuImageRenderer::~GpuImageRenderer() {
  if (QOpenGLContext::currentContext()) currentGl()->glDeleteVertexArrays(1, &vertexArray_);
}

Image GpuImageRenderer::draw(const WoodModel* model, const BoardWood* board, glm::vec3 origin,
                             glm::vec3 pixelRight, glm::vec3 pixelDown, glm::ivec2 size, int faceIndex,
                             bool clip, int channels) {
  QOpenGLFramebufferObjectFormat format;
  format.setInternalTextureFormat(0x8814);  // GL_RGBA32F: no 8-bit rounding before the comparison
  QOpenGLFramebufferObject fbo(size.x, size.y, format);
  if (!fbo.isValid() || !fbo.bind()) throw std::runtime_error("cannot create a float framebuffer");
  QOpenGLExtraFunctions* f = currentGl();
  f->glViewport(0, 0, size.x, size.y);
  f->glDisable(GL_BLEND);
  f->glDisable(GL_DEPTH_TEST);
  WoodProgram& wood = board ? *boardProgram_ : *program_;
  QOpenGLShaderProgram& program = wood.program();
  program.bind();
  if (board) {
    boardTextures_->upload(*board, 0);
    boardTextures_->bind(program, 1);
  } else {
    wood.setModel(*model);
  }
  program.setUniformValue("u_planeOrigin", toQt(origin));
  program.setUniformValue("u_pixelRight", toQt(pixelRight));
  program.setUniformValue("u_pixelDown", toQt(pixelDown));
  program.setUniformValue("u_imageHeight", static_cast<float>(size.y));
  program.setUniformValue("u_faceIndex", faceIndex);
  program.setUniformValue("u_blockHalfSize",
                          toQt(board ? board->board.block().halfSize() : model->block().halfSize()));
  program.setUniformValue("u_clipToBlock", clip);
  f->glBindVertexArray(vertexArray_);
  f->glDrawArrays(GL_TRIANGLES, 0, 3);

  std::vector<float> rgba(static_cast<std::size_t>(size.x) * size.y * 4);
  f->glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, rgba.data());
  fbo.release();
  program.release();
  Image image(size.x, size.y, channels);
  for (int y = 0; y < size.y; ++y)  // OpenGL rows are bottom-up
    for (int x = 0; x < size.x; ++x) {
      const float* s = &rgba[(static_cast<std::size_t>(size.y - 1 - y) * size.x + x) * 4];
      std::copy_n(s, channels, image.pixel(x, y));
    }
  return image;
}

Image GpuImageRenderer::renderFace(const WoodModel& model, FaceId face, glm::ivec2 size) {
  const Block& block = model.block();
  const glm::vec3 origin = block.imageToBlock(face, {0, 0}, size);
  const glm::vec3 right = block.imageToBlock(face, {1, 0}, size) - origin;
  const glm::vec3 down = block.imageToBlock(face, {0, 1}, size) - origin;
  return draw(&model, nullptr, origin, right, down, size, faceIndex(face), false, 3);
}

Image GpuImageRenderer::renderCut(const WoodModel& model, const CutPlane& plane, float pxPerMm) {
  return drawCut(&model, nullptr, model.block(), plane, pxPerMm);
}

Image GpuImageRenderer::renderBoardCut(const BoardWood& wood, const CutPlane& plane, float pxPerMm) {
  if (!boardProgram_) {
    boardProgram_ = std::make_unique<WoodProgram>("image_plane.vert", "image_plane.frag", WoodSource::Board);
    boardTextures_ = std::make_unique<BoardWoodTextures>();
  }
  return drawCut(nullptr, &wood, wood.board.block(), plane, pxPerMm);
}

Image GpuImageRenderer::drawCut(const WoodModel* model, const BoardWood* board, const Block& block,
                                const CutPlane& plane, float pxPerMm) {
  const auto bounds = plane.boundsInBlock(block);
  if (!bounds) throw InputError("the cut plane does not pass through the block");
  const glm::vec2 extent = bounds->max - bounds->min;
  const glm::ivec2 size(std::max(1, static_cast<int>(std::ceil(extent.x * pxPerMm - 1e-3f))),
                        std::max(1, static_cast<int>(std::ceil(extent.y * pxPerMm - 1e-3f))));
  const glm::vec3 origin = plane.toBlock({bounds->min.x, bounds->max.y});  // same layout as core's renderCut
  return draw(model, board, origin, plane.right() / pxPerMm, -plane.up() / pxPerMm, size, -1, true, 4);
}

}  // namespace kerf
