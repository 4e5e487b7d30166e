#pragma once
// Faces and cuts of the wood model rendered on the GPU into a float framebuffer: the GLSL twin of
// core/render/renderers.hpp (one sample per pixel). Used by the CPU/GPU parity test, and by views
// that need a true-scale picture of a plane. Needs a current OpenGL 3.3 core context.
#include <memory>

#include "geometry/cut_plane.hpp"
#include "io/image.hpp"
#include "render/wood_model.hpp"

namespace kerf {

class WoodProgram;

class GpuImageRenderer {
 public:
  GpuImageRenderer();  // compiles the program; throws std::runtime_error
  ~GpuImageRenderer();

  Image renderFace(const WoodModel& model, FaceId face, glm::ivec2 size);         // RGB
  Image renderCut(const WoodModel& model, const CutPlane& plane, float pxPerMm);  // RGBA

 private:
  Image draw(const WoodModel& model, glm::vec3 origin, glm::vec3 pixelRight, glm::vec3 pixelDown,
             glm::ivec2 size, int faceIndex, bool clip, int channels);
  std::unique_ptr<WoodProgram> program_;
  unsigned vertexArray_ = 0;
};

}  // namespace kerf
