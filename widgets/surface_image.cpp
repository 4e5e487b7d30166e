#include "surface_image.hpp"

#include <glm/geometric.hpp>

namespace kerf {

glm::vec2 SurfaceImage::textureCoordinates(glm::vec3 blockPoint) const {
  const glm::vec3 d = blockPoint - grid.origin;
  // right and down are orthogonal: the pixel coordinates are the projections onto them.
  const float x = glm::dot(d, grid.right) / glm::dot(grid.right, grid.right);
  const float y = glm::dot(d, grid.down) / glm::dot(grid.down, grid.down);
  return {(x + 0.5f) / grid.width, (y + 0.5f) / grid.height};
}

}  // namespace kerf
