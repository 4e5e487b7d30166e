#include "orbit_camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace kerf {

OrbitCamera::OrbitCamera() = default;

void OrbitCamera::setViewportSize(glm::vec2 sizePx) {
  viewport_ = glm::max(sizePx, glm::vec2(1.0f));
}

void OrbitCamera::setScene(glm::vec3 center, float radius) {
  sceneCenter_ = center;
  sceneRadius_ = std::max(radius, 1e-3f);
  setDistance(distance_);
}

void OrbitCamera::setAngles(float yawDeg, float pitchDeg) {
  if (!std::isfinite(yawDeg) || !std::isfinite(pitchDeg)) return;
  yaw_ = std::remainder(yawDeg, 360.0f);
  if (yaw_ <= -180.0f) yaw_ += 360.0f;
  pitch_ = std::clamp(pitchDeg, -90.0f, 90.0f);
}

void OrbitCamera::setDistance(float mm) {
  if (!std::isfinite(mm)) return;
  distance_ = std::clamp(mm, sceneRadius_ * 0.05f, sceneRadius_ * 200.0f);
}

void OrbitCamera::setFieldOfView(float verticalDeg) {
  if (std::isfinite(verticalDeg)) fovY_ = std::clamp(verticalDeg, 5.0f, 120.0f);
}

glm::vec3 OrbitCamera::forward() const {
  const float y = glm::radians(yaw_), p = glm::radians(pitch_);
  return -glm::vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
}

glm::vec3 OrbitCamera::right() const {
  const float y = glm::radians(yaw_);
  return {std::cos(y), 0.0f, -std::sin(y)};
}

glm::vec3 OrbitCamera::up() const {
  return glm::normalize(glm::cross(right(), forward()));
}

glm::vec3 OrbitCamera::eye() const {
  return target_ - distance_ * forward();
}

glm::mat4 OrbitCamera::viewMatrix() const {
  return glm::lookAt(eye(), target_, up());
}

float OrbitCamera::nearPlane() const {
  const float d = glm::length(eye() - sceneCenter_);
  return std::max(d - 1.5f * sceneRadius_, 0.01f * std::min(distance_, sceneRadius_));
}

float OrbitCamera::farPlane() const {
  const float d = glm::length(eye() - sceneCenter_);
  return std::max(d + 1.5f * sceneRadius_, nearPlane() * 2.0f);
}

glm::mat4 OrbitCamera::projectionMatrix() const {
  return glm::perspective(glm::radians(fovY_), viewport_.x / viewport_.y, nearPlane(), farPlane());
}

void OrbitCamera::orbit(glm::vec2 deltaPx) {
  setAngles(yaw_ - deltaPx.x * kDegreesPerPixel, pitch_ + deltaPx.y * kDegreesPerPixel);
}

void OrbitCamera::pan(glm::vec2 deltaPx) {
  const float mmPerPx = 1.0f / pixelsPerMm(target_);
  target_ += mmPerPx * (-deltaPx.x * right() + deltaPx.y * up());
}

void OrbitCamera::zoom(float steps, std::optional<glm::vec2> cursorPx) {
  if (!std::isfinite(steps)) return;
  const float oldDistance = distance_;
  setDistance(distance_ * std::pow(0.85f, steps));
  const float factor = distance_ / oldDistance;
  if (!cursorPx) return;
  // Scale the whole camera set-up about the point under the cursor on the target's depth plane: that
  // point keeps its pixel.
  const glm::vec3 f = forward();
  const glm::vec3 eyeBefore = target_ - oldDistance * f;
  Ray ray = rayThrough(*cursorPx);
  ray.origin = eyeBefore;
  const float t = oldDistance / std::max(glm::dot(ray.direction, f), 1e-4f);
  const glm::vec3 anchor = ray.at(t);
  target_ = anchor + (target_ - anchor) * factor;
}

void OrbitCamera::fit(glm::vec3 halfSize, glm::vec3 center) {
  const float radius = glm::length(halfSize);
  setScene(center, radius);
  target_ = center;
  const float halfY = glm::radians(fovY_) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * viewport_.x / viewport_.y);
  const float half = std::min(halfX, halfY);
  setDistance(radius / std::sin(half) * 1.04f);
}

void OrbitCamera::setView(View view) {
  switch (view) {
    case View::Front:
      setAngles(0.0f, 0.0f);
      break;
    case View::Back:
      setAngles(180.0f, 0.0f);
      break;
    case View::Right:
      setAngles(90.0f, 0.0f);
      break;
    case View::Left:
      setAngles(-90.0f, 0.0f);
      break;
    case View::Top:
      setAngles(0.0f, 90.0f);
      break;
    case View::Bottom:
      setAngles(0.0f, -90.0f);
      break;
  }
}

Ray OrbitCamera::rayThrough(glm::vec2 px) const {
  const float tanY = std::tan(glm::radians(fovY_) * 0.5f);
  const float tanX = tanY * viewport_.x / viewport_.y;
  const float ndcX = 2.0f * px.x / viewport_.x - 1.0f;
  const float ndcY = 1.0f - 2.0f * px.y / viewport_.y;
  const glm::vec3 dir = forward() + ndcX * tanX * right() + ndcY * tanY * up();
  return {eye(), glm::normalize(dir)};
}

glm::vec3 OrbitCamera::project(glm::vec3 world) const {
  const glm::vec3 d = world - eye();
  const float depth = glm::dot(d, forward());
  const float tanY = std::tan(glm::radians(fovY_) * 0.5f);
  const float tanX = tanY * viewport_.x / viewport_.y;
  const float safe = std::abs(depth) < 1e-6f ? 1e-6f : depth;
  const float ndcX = glm::dot(d, right()) / (safe * tanX);
  const float ndcY = glm::dot(d, up()) / (safe * tanY);
  return {(ndcX + 1.0f) * 0.5f * viewport_.x, (1.0f - ndcY) * 0.5f * viewport_.y, depth};
}

float OrbitCamera::pixelsPerMm(glm::vec3 world) const {
  const float depth = std::max(glm::dot(world - eye(), forward()), 1e-4f);
  const float tanY = std::tan(glm::radians(fovY_) * 0.5f);
  return viewport_.y / (2.0f * depth * tanY);
}

}  // namespace kerf
