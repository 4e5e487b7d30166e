#include "gpu/board_wood_textures.hpp"

#include <QOpenGLShaderProgram>
#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl_helpers.hpp"
#include "gpu/knot_tables.hpp"

namespace kerf {

BoardWoodTextures::BoardWoodTextures() : tables_(std::make_unique<KnotTables>()) {
  currentGl()->glGenTextures(1, &cellsTexture_);
}

BoardWoodTextures::~BoardWoodTextures() {
  if (QOpenGLContext::currentContext()) currentGl()->glDeleteTextures(1, &cellsTexture_);
}

void BoardWoodTextures::upload(const BoardWood& wood, int unit) {
  const bool newLog = wood.field != field_ || wood.colors != colors_;
  if (newLog) {
    // Every knot of the log, in the log's order: the grid's lists are log knot indices.
    tables_->uploadLog(*wood.field, *wood.colors, wood.field->allKnots(), unit);
    field_ = wood.field;
    colors_ = wood.colors;
  }
  const Board& b = wood.board;
  const bool moved = !boardValid_ || b.center != board_.center || b.size != board_.size ||
                     b.rotationDeg != board_.rotationDeg;
  if (!newLog && !moved) return;
  grid_ = buildKnotCellGrid(*wood.field, b, knotGridCells(b.size));
  board_ = b;
  boardValid_ = true;
  tables_->uploadKnotList(grid_.list, unit);
  QOpenGLExtraFunctions* f = currentGl();
  f->glActiveTexture(GL_TEXTURE0 + unit);
  f->glBindTexture(GL_TEXTURE_3D, cellsTexture_);
  const PackedRowsUpload packed;
  f->glTexImage3D(GL_TEXTURE_3D, 0, GL_RG32I, grid_.cells.x, grid_.cells.y, grid_.cells.z, 0, GL_RG_INTEGER,
                  GL_INT, grid_.ranges.data());
  f->glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
  f->glBindTexture(GL_TEXTURE_3D, 0);
  f->glActiveTexture(GL_TEXTURE0);
}

void BoardWoodTextures::bind(QOpenGLShaderProgram& p, int firstUnit) const {
  tables_->bind(p, firstUnit);
  const int cellsUnit = firstUnit + KnotTables::kTextureCount;
  QOpenGLExtraFunctions* f = currentGl();
  f->glActiveTexture(GL_TEXTURE0 + cellsUnit);
  f->glBindTexture(GL_TEXTURE_3D, cellsTexture_);
  f->glActiveTexture(GL_TEXTURE0);
  p.setUniformValue("u_cells", cellsUnit);
  const glm::mat3 axes = board_.axes();
  f->glUniformMatrix3fv(p.uniformLocation("u_boardAxes"), 1, GL_FALSE, glm::value_ptr(axes));
  p.setUniformValue("u_boardCenter", toQt(board_.center));
  p.setUniformValue("u_boardSize", toQt(board_.size));
  f->glUniform3i(p.uniformLocation("u_cellCount"), grid_.cells.x, grid_.cells.y, grid_.cells.z);
}

}  // namespace kerf
