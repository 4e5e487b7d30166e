#pragma once
// The cut plane's handles in the 3D view and the maths of dragging them; no Qt or OpenGL, so it can be
// unit-tested. Viewport3D draws what this class describes and feeds it the mouse.
//
// Handles (all centred on the pivot, the centroid of the cut surface):
// - Surface: the cut surface itself. Dragging moves the plane along its normal (offset).
// - Arrow: a short arrow along the normal; dragging it moves the plane like the surface does (for when
//   the surface faces away from the viewer).
// - AzimuthRing: a horizontal ring (around the block's y axis); dragging around it changes the azimuth.
// - ElevationRing: a vertical ring through the normal and y; dragging around it changes the elevation
//   (over the top, the azimuth flips by 180 degrees).
// Rotations pivot about the cut surface's centroid: the plane keeps passing through it, so the offset
// follows (offset = dot(pivot, normal)).
//
// Snapping while dragging: the angle being dragged snaps to multiples of 90 degrees (a principal plane)
// within 3 degrees; with Shift held it snaps to 15 degree steps (CutPlaneSetting::snapped's rule), and
// offset drags round to whole millimetres. Offsets are kept inside the block.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "geometry/block.hpp"
#include "geometry/cut_plane.hpp"
#include "orbit_camera.hpp"

namespace kerf {

// The polygon where `plane` meets the block (3 to 6 corners), counter-clockwise seen from the side the
// normal points to; empty when the plane misses the block or only touches an edge.
std::vector<glm::vec3> cutPolygon(const Block& block, const CutPlane& plane);

class CutGizmo {
 public:
  enum class Handle { None, Surface, Arrow, AzimuthRing, ElevationRing };

  static constexpr float kPickTolerancePx = 7.0f;
  static constexpr float kSnapStepDeg = 15.0f;      // with Shift
  static constexpr float kPrincipalSnapDeg = 3.0f;  // always

  void setBlock(const Block& block);
  const Block& block() const { return block_; }
  // Ignored while a drag is under way (the drag's own result wins until endDrag()).
  void setSetting(const CutPlaneSetting& setting);
  const CutPlaneSetting& setting() const { return setting_; }

  bool meetsBlock() const { return polygon_.size() >= 3; }
  const std::vector<glm::vec3>& polygon() const { return polygon_; }  // of the current setting
  glm::vec3 normal() const { return setting_.normal(); }
  glm::vec3 pivot() const;  // centroid of the cut surface (fixed during a ring drag)
  float ringRadius() const;
  float arrowLength() const { return 0.7f * ringRadius(); }

  // Ring points: AzimuthRing at azimuth `angle` (radians, CutPlaneSetting's convention: from +x towards
  // -z), ElevationRing at `angle` above the horizontal, on the normal's side. The normal itself lies at
  // angle = azimuth (resp. elevation) on its ring.
  glm::vec3 ringPoint(Handle ring, float angleRad) const;
  std::vector<glm::vec3> ringPolyline(Handle ring, int segments = 96) const;  // closed (first == last)
  glm::vec3 arrowTip() const { return pivot() + arrowLength() * normal(); }

  // What is under widget pixel `px`: a ring or the arrow within kPickTolerancePx (front halves of the
  // rings first), else the cut surface where it faces the viewer, else None.
  Handle pick(const OrbitCamera& camera, glm::vec2 px) const;

  // Dragging: begin with the handle from pick(), then drag() with every mouse position (returns the new
  // setting, also kept), endDrag() on release. cancelDrag() restores the setting the drag began from.
  bool beginDrag(Handle handle, const OrbitCamera& camera, glm::vec2 px);
  CutPlaneSetting drag(const OrbitCamera& camera, glm::vec2 px, bool shiftSnap);
  void endDrag();
  CutPlaneSetting cancelDrag();
  bool dragging() const { return dragHandle_ != Handle::None; }
  Handle dragHandle() const { return dragHandle_; }
  CutPlaneSetting dragStartSetting() const { return start_; }

  // The largest |offset| for which a plane with this normal still cuts the block.
  float maxOffset(glm::vec3 normal) const;
  // The snapping rule for one angle (degrees).
  static float snapAngle(float deg, bool shiftSnap);

 private:
  void updatePolygon();
  glm::vec3 ringAxis1(Handle ring) const;
  glm::vec3 ringAxis2(Handle ring) const;
  float cursorAngle(const OrbitCamera& camera, glm::vec2 px) const;

  Block block_;
  CutPlaneSetting setting_;
  std::vector<glm::vec3> polygon_;

  Handle dragHandle_ = Handle::None;
  CutPlaneSetting start_;
  glm::vec2 startPx_{0.0f}, lastPx_{0.0f};
  glm::vec3 dragPivot_{0.0f};
  float startAzimuthRad_ = 0.0f;     // the elevation ring's plane, fixed for the drag
  glm::vec2 offsetScreenDir_{0.0f};  // pixels per mm of offset
  bool tangentMode_ = false;
  float lastCursorAngle_ = 0.0f, turned_ = 0.0f;
  float grabAngle_ = 0.0f;  // the ring angle the cursor grabbed (edge-on rings)
};

}  // namespace kerf
