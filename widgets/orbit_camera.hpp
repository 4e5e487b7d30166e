#pragma once
// The 3D view's camera: it orbits a target point (yaw/pitch at a distance), zooms (towards the cursor),
// pans, frames a block, and gives the view/projection matrices and picking rays. Pure math (GLM), no
// Qt or OpenGL, so it can be unit-tested.
//
// Angles: yaw turns around the block's +y axis, pitch lifts the eye above the xz plane. The eye sits at
//   target + distance * (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)),
// so yaw 0 / pitch 0 looks at face A (+z) from the front, yaw 90 at face E (+x), pitch 90 down onto
// face B (+y). Screen "right" is always (cos yaw, 0, -sin yaw), so the view stays well defined straight
// above or below the block (then screen "up" is -z from above, +z from below: face B and D upright as in
// their face images).
//
// Pixels: widget (logical) pixels, x to the right, y downward, (0, 0) at the top-left corner of the
// viewport; the centre of the view is (width / 2, height / 2).
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

namespace kerf {

struct Ray {
  glm::vec3 origin;
  glm::vec3 direction;  // unit
  glm::vec3 at(float t) const { return origin + t * direction; }
};

class OrbitCamera {
 public:
  // The principal views of the keyboard (numpad 1/3/7 as in Blender, Ctrl for the opposite side).
  enum class View { Front, Back, Right, Left, Top, Bottom };

  OrbitCamera();

  // Viewport size in widget pixels (at least 1 x 1).
  void setViewportSize(glm::vec2 sizePx);
  glm::vec2 viewportSize() const { return viewport_; }

  // What the near/far planes must enclose: a sphere (the block's bounding sphere).
  void setScene(glm::vec3 center, float radius);
  glm::vec3 sceneCenter() const { return sceneCenter_; }
  float sceneRadius() const { return sceneRadius_; }

  void setTarget(glm::vec3 target) { target_ = target; }
  glm::vec3 target() const { return target_; }
  // yaw wraps to (-180, 180]; pitch is clamped to [-90, 90].
  void setAngles(float yawDeg, float pitchDeg);
  float yawDeg() const { return yaw_; }
  float pitchDeg() const { return pitch_; }
  // Clamped to [sceneRadius * 0.05, sceneRadius * 200].
  void setDistance(float mm);
  float distance() const { return distance_; }
  void setFieldOfView(float verticalDeg);  // clamped to [5, 120]
  float fieldOfViewDeg() const { return fovY_; }

  glm::vec3 eye() const;
  glm::vec3 forward() const;  // unit, from the eye towards the target
  glm::vec3 right() const;    // unit, screen +x
  glm::vec3 up() const;       // unit, screen -y (upward on screen)

  glm::mat4 viewMatrix() const;
  glm::mat4 projectionMatrix() const;  // perspective, OpenGL clip space
  glm::mat4 viewProjection() const { return projectionMatrix() * viewMatrix(); }
  float nearPlane() const;
  float farPlane() const;

  // Left-drag: `deltaPx` of mouse motion turns the view by kDegreesPerPixel per pixel (dragging right
  // turns the block to the right, dragging down tilts its top towards the viewer).
  static constexpr float kDegreesPerPixel = 0.4f;
  void orbit(glm::vec2 deltaPx);
  // Right/middle-drag: the point under the cursor at the target's depth follows the mouse.
  void pan(glm::vec2 deltaPx);
  // Wheel: `steps` notches (positive = closer, 1 notch = 15% of the distance). With `cursorPx` the
  // point under the cursor at the target's depth stays under the cursor.
  void zoom(float steps, std::optional<glm::vec2> cursorPx = std::nullopt);

  // Looks at the box [-halfSize, halfSize] (centred at `center`) from the current angles, from just
  // far enough that its bounding sphere fits the view; also sets the scene sphere.
  void fit(glm::vec3 halfSize, glm::vec3 center = glm::vec3(0.0f));
  void setView(View view);  // angles of a principal view; target and distance unchanged

  // The ray from the eye through widget pixel `px` (continuous coordinates).
  Ray rayThrough(glm::vec2 px) const;
  // Widget pixel of a world point (x, y) and its depth along the view direction (z, mm; negative
  // behind the eye).
  glm::vec3 project(glm::vec3 world) const;
  // Widget pixels per mm of a small length at `world`, facing the camera (for handle sizes).
  float pixelsPerMm(glm::vec3 world) const;

 private:
  glm::vec2 viewport_{800.0f, 600.0f};
  glm::vec3 sceneCenter_{0.0f};
  float sceneRadius_ = 35.0f;
  glm::vec3 target_{0.0f};
  float yaw_ = 35.0f, pitch_ = 25.0f;
  float distance_ = 120.0f;
  float fovY_ = 30.0f;
};

}  // namespace kerf
