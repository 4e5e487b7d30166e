#include "field/pith_axis.hpp"

#include <glm/trigonometric.hpp>

#include "util/error.hpp"

namespace kerf {

PithAxis PithAxis::fromAngles(glm::vec3 origin, float tiltDeg, float azimuthDeg) {
  const float t = glm::radians(tiltDeg), a = glm::radians(azimuthDeg);
  return fromDirection(origin, {std::sin(t) * std::cos(a), std::cos(t), -std::sin(t) * std::sin(a)});
}

PithAxis PithAxis::fromDirection(glm::vec3 origin, glm::vec3 direction) {
  const float len = glm::length(direction);
  if (!std::isfinite(len) || len < 1e-12f || !std::isfinite(origin.x + origin.y + origin.z)) {
    throw InputError("the pith axis needs a finite origin and a non-zero direction");
  }
  PithAxis axis;
  axis.origin = origin;
  axis.direction = direction / len;
  const glm::vec3 d = axis.direction;
  // Least-aligned block axis; ties prefer z, then x (so a pith along y has azimuth 0 towards +z).
  glm::vec3 e(0, 0, 1);
  if (std::abs(d.x) < std::abs(d.z) && std::abs(d.x) <= std::abs(d.y))
    e = {1, 0, 0};
  else if (std::abs(d.y) < std::abs(d.z) && std::abs(d.y) < std::abs(d.x))
    e = {0, 1, 0};
  axis.reference = glm::normalize(e - glm::dot(e, d) * d);
  axis.binormal = glm::cross(d, axis.reference);
  return axis;
}

}  // namespace kerf
