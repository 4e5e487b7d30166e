#pragma once
// The log's tables for shaders/knots.glsl as textures: the stem (pith, radii), a list of knots (their
// skeletons, death distances and core's noise tables, in the order given), the colour map, and the knot
// list evaluateKnots() walks (u_tileKnots). Shared by GpuBoardRenderer (board faces, culled per tile)
// and the editor's board wood (BoardWoodTextures, culled per 3D cell). Needs a current OpenGL 3.3
// core context for every call, the one it was created in.
#include <span>
#include <vector>

#include "field/knot_field.hpp"

class QOpenGLShaderProgram;

namespace kerf {

class KnotTables {
 public:
  static constexpr int kTextureCount = 7;  // pith, radii, skeletons, knot info, noise, colours, knot list

  KnotTables();
  ~KnotTables();
  KnotTables(const KnotTables&) = delete;
  KnotTables& operator=(const KnotTables&) = delete;

  // The stem, the knots `knots` (indices into field.log().knots; the shader's knot index k is the
  // position in this list) and the colour map. Uploads through texture unit `unit`.
  void uploadLog(const KnotField& field, const WoodColorMap& colors, std::span<const int> knots, int unit);
  // The knot list the shader walks (values: shader knot indices), wrapped into rows.
  void uploadKnotList(std::vector<int> list, int unit);

  // With `program` bound: binds the textures to units firstUnit .. firstUnit + kTextureCount - 1 and sets
  // their samplers, the stem and colour-map uniforms and the schema's knot parameters from the field's
  // KnotSettings.
  void bind(QOpenGLShaderProgram& program, int firstUnit) const;

  int knotCount() const { return knotCount_; }

 private:
  unsigned textures_[kTextureCount] = {};
  KnotSettings settings_;
  float heightStep_ = 1.0f;
  int slices_ = 0, azimuths_ = 0, colorCount_ = 0, knotCount_ = 0;
};

// A 2D table read with texelFetch only (nearest, no mipmaps, so it is complete), through `unit`;
// throws std::runtime_error past GL_MAX_TEXTURE_SIZE.
void uploadTexelTable(unsigned texture, int unit, int internalFormat, int width, int height, unsigned format,
                      unsigned type, const void* data);

}  // namespace kerf
