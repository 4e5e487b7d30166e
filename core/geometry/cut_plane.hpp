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
#include <vector>

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

  // The plane's intersection with the block: a convex polygon (3 to 6 corners, block mm), counter-
  // clockwise seen from the normal's side; empty when the plane misses the block or only grazes it.
  std::vector<glm::vec3> polygonInBlock(const Block& block) const;
  // The rectangle in plane coordinates that bounds that polygon, or nothing when there is none.
  std::optional<PlaneRect> boundsInBlock(const Block& block) const;

 private:
  glm::vec3 point_, normal_, right_, up_;
};

}  // namespace kerf

namespace kerf {

// A cut plane as a person sets it: an offset from the block centre along the normal, and the normal's
// direction as two angles (what the editor's numeric fields and the gizmo edit).
// normal = (cos(elevation) cos(azimuth), sin(elevation), -cos(elevation) sin(azimuth)):
// azimuth 0 / elevation 0 is +x (a plane parallel to faces C and E), elevation 90 is +y (a cross-section
// parallel to B and D); azimuth turns around y from +x towards -z (azimuth 90 is -z), as the pith lean.
struct CutPlaneSetting {
  float offsetMm = 0.0f;
  float azimuthDeg = 0.0f;
  float elevationDeg = 0.0f;

  glm::vec3 normal() const;
  CutPlane plane() const { return CutPlane(offsetMm * normal(), normal()); }
  static CutPlaneSetting fromPlane(const CutPlane& plane);  // offset measured from the block centre

  // Angles rounded to multiples of `stepDeg` (the gizmo's snapping; 90 gives the principal planes).
  CutPlaneSetting snapped(float stepDeg) const;
  bool operator==(const CutPlaneSetting&) const = default;
};

}  // namespace kerf
