#pragma once
// Faces and cuts of the wood model rendered on the GPU into a float framebuffer: the GLSL twin of
// core/render/renderers.hpp (one sample per pixel). Used by the CPU/GPU parity test, and by views
// that need a true-scale picture of a plane. Needs a current OpenGL 3.3 core context.
#include <memory>

#include "geometry/cut_plane.hpp"
#include "io/image.hpp"
#include "render/board_wood.hpp"
#include "render/wood_model.hpp"

namespace kerf {

class BoardWoodTextures;
class WoodProgram;

class GpuImageRenderer {
 public:
  GpuImageRenderer();  // compiles the program; throws std::runtime_error
  ~GpuImageRenderer();

  Image renderFace(const WoodModel& model, FaceId face, glm::ivec2 size);         // RGB
  Image renderCut(const WoodModel& model, const CutPlane& plane, float pxPerMm);  // RGBA
  // The cut through a board of a log, as the cut panel draws it in log mode (shaders/board_wood.glsl,
  // knots culled per grid cell); the pixel layout of renderCut. RGBA, alpha 0 outside the board.
  Image renderBoardCut(const BoardWood& wood, const CutPlane& plane, float pxPerMm);

 private:
  // One of `model` and `board` (the other null) on the image plane.
  Image draw(const WoodModel* model, const BoardWood* board, glm::vec3 origin, glm::vec3 pixelRight,
             glm::vec3 pixelDown, glm::ivec2 size, int faceIndex, bool clip, int channels);
  Image drawCut(const WoodModel* model, const BoardWood* board, const Block& block, const CutPlane& plane,
                float pxPerMm);
  std::unique_ptr<WoodProgram> program_;
  std::unique_ptr<WoodProgram> boardProgram_;  // built on first use
  std::unique_ptr<BoardWoodTextures> boardTextures_;
  unsigned vertexArray_ = 0;
};

}  // namespace kerf
