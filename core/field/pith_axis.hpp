#pragma once
// The pith axis (O, V) and the cylindrical coordinates it sets up (Mokume Sec. 5.2.1, Fig. 13):
// height h along the axis, radius r from it, azimuth theta around it.
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace kerf {

struct Cylindrical {
  float height;          // mm along V from O
  float radius;          // mm from the axis line
  float azimuth;         // radians in (-pi, pi], measured from PithAxis::reference towards binormal
  glm::vec3 radial;      // unit vector from the axis to the point (reference when on the axis)
  glm::vec3 tangential;  // unit vector V x radial: direction of increasing azimuth
  float x, y;            // cross-section coordinates: radius*cos(azimuth), radius*sin(azimuth)
};

struct PithAxis {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0, 1, 0};  // unit
  glm::vec3 reference{0, 0, 1};  // unit, perpendicular to direction: azimuth 0
  glm::vec3 binormal{1, 0, 0};   // direction x reference: azimuth +90 degrees

  // tilt: angle from the block's +y axis; azimuth: lean direction around y measured from +x towards -z.
  static PithAxis fromAngles(glm::vec3 origin, float tiltDeg, float azimuthDeg);
  // Any non-zero direction. The azimuth reference is the block axis least aligned with the pith,
  // made perpendicular to it, so it is well defined for every direction.
  static PithAxis fromDirection(glm::vec3 origin, glm::vec3 direction);

  // withAzimuth = false skips the atan2 (azimuth left 0) where only the frame and radius are needed.
  Cylindrical toCylindrical(glm::vec3 p, bool withAzimuth = true) const {
    const glm::vec3 rel = p - origin;
    const float h = glm::dot(rel, direction);
    const float x = glm::dot(rel, reference);
    const float y = glm::dot(rel, binormal);
    const float r = std::sqrt(x * x + y * y);
    Cylindrical c;
    c.height = h;
    c.radius = r;
    c.azimuth = withAzimuth ? std::atan2(y, x) : 0.0f;
    c.x = x;
    c.y = y;
    if (r > 1e-12f) {
      c.radial = (x * reference + y * binormal) / r;
    } else {
      c.radial = reference;
    }
    c.tangential = glm::cross(direction, c.radial);
    return c;
  }
};

}  // namespace kerf
