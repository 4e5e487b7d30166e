#pragma once
// A board's wood (render/board_wood.hpp) on the GPU for shaders/board_wood.glsl: the log's tables with
// all its knots (KnotTables, re-uploaded only when the field or the colour map change) and the 3D grid
// of knot lists over the board (rebuilt when the board moves). Needs a current OpenGL 3.3 core context,
// the one it was created in.
#include <memory>

#include "render/board_wood.hpp"

class QOpenGLShaderProgram;

namespace kerf {

class KnotTables;

class BoardWoodTextures {
 public:
  static constexpr int kTextureCount = 8;  // KnotTables' seven and the grid

  BoardWoodTextures();
  ~BoardWoodTextures();
  BoardWoodTextures(const BoardWoodTextures&) = delete;
  BoardWoodTextures& operator=(const BoardWoodTextures&) = delete;

  // Uploads what changed since the last call, through texture unit `unit`.
  void upload(const BoardWood& wood, int unit);
  // With `program` bound: binds the textures to units firstUnit .. firstUnit + kTextureCount - 1 and sets
  // the samplers and uniforms of knots.glsl and board_wood.glsl.
  void bind(QOpenGLShaderProgram& program, int firstUnit) const;

  const KnotCellGrid& grid() const { return grid_; }

 private:
  std::unique_ptr<KnotTables> tables_;
  unsigned cellsTexture_ = 0;
  std::shared_ptr<const KnotField> field_;
  std::shared_ptr<const WoodColorMap> colors_;
  Board board_;
  bool boardValid_ = false;
  KnotCellGrid grid_;
};

}  // namespace kerf
