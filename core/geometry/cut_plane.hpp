#pragma once
// An arbitrary cutting plane through the block, with its own 2D image frame.
//
// Orientation of a cut image (docs/coordinates.md): you look at the plane from the side its normal
// points to. "Up" is the block's +y axis projected onto the plane, unless the normal is closest to
// the y axis; then up is -z for a normal towards +y and +z for a normal towards -y. "Right" is
// up x normal. With these rules a plane through a face, normal outward, shows the face exactly as the
// face image does (A..F).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "geometry/block.hpp"

namespace kerf {

struct PlaneRect {
  glm::vec2 min;  // (right, up) coordinates in mm, relative to the plane's point
  glm::vec2 max;
};

class CutPlane {
 public:
  // Throws InputError for a zero or non-finite normal or a non-finite point.
  CutPlane(glm::vec3 pointMm, glm::vec3 normal);

  glm::vec3 point() const { return point_; }
  glm::vec3 normal() const { return normal_; }
  glm::vec3 right() const { return right_; }
  glm::vec3 up() const { return up_; }

  glm::vec3 toBlock(glm::vec2 planeMm) const { return point_ + planeMm.x * right_ + planeMm.y * up_; }
  glm::vec2 toPlane(glm::vec3 p) const;

  // The rectangle in plane coordinates that bounds the plane's intersection with the block,
  // or nothing when the plane misses the block.
  std::optional<PlaneRect> boundsInBlock(const Block& block) const;

 private:
  glm::vec3 point_, normal_, right_, up_;
};

}  // namespace kerf
