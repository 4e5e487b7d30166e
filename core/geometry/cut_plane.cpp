#include "geometry/cut_plane.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

#include "util/error.hpp"

namespace kerf {

CutPlane::CutPlane(glm::vec3 point, glm::vec3 normal) : point_(point) {
  const float len = glm::length(normal);
  if (!std::isfinite(len) || len < 1e-8f || !std::isfinite(point.x + point.y + point.z)) {
    throw InputError("a cut plane needs a finite point and a non-zero normal");
  }
  normal_ = normal / len;
  const float ax = std::abs(normal_.x), ay = std::abs(normal_.y), az = std::abs(normal_.z);
  glm::vec3 upHint(0, 1, 0);
  if (ay >= ax && ay >= az) upHint = glm::vec3(0, 0, normal_.y > 0 ? -1.0f : 1.0f);
  up_ = glm::normalize(upHint - glm::dot(upHint, normal_) * normal_);
  right_ = glm::normalize(glm::cross(up_, normal_));
  up_ = glm::cross(normal_, right_);
}

glm::vec2 CutPlane::toPlane(glm::vec3 p) const {
  const glm::vec3 d = p - point_;
  return {glm::dot(d, right_), glm::dot(d, up_)};
}

std::vector<glm::vec3> CutPlane::polygonInBlock(const Block& block) const {
  const glm::vec3 h = block.halfSize();
  std::vector<glm::vec3> points;
  const auto add = [&](glm::vec3 p) {
    for (const glm::vec3& q : points)
      if (glm::length(q - p) < 1e-4f * (1.0f + glm::length(h))) return;
    points.push_back(p);
  };
  // Intersect the plane with the 12 box edges: along each axis, 4 edges.
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int corner = 0; corner < 4; ++corner) {
      glm::vec3 start(0.0f);
      start[a1] = (corner & 1) ? h[a1] : -h[a1];
      start[a2] = (corner & 2) ? h[a2] : -h[a2];
      start[axis] = -h[axis];
      glm::vec3 dir(0.0f);
      dir[axis] = 2.0f * h[axis];
      const float denom = glm::dot(normal_, dir);
      const float num = glm::dot(normal_, point_ - start);
      if (std::abs(denom) < 1e-9f) {
        if (std::abs(num) <= 1e-5f) add(start), add(start + dir);  // the edge lies in the plane
        continue;
      }
      const float t = num / denom;
      if (t < -1e-6f || t > 1.0f + 1e-6f) continue;
      add(start + std::clamp(t, 0.0f, 1.0f) * dir);
    }
  }
  if (points.size() < 3) return {};
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : points) centre += p;
  centre /= static_cast<float>(points.size());
  const auto angle = [&](const glm::vec3& p) {  // right x up = normal: increasing angle is CCW from +n
    return std::atan2(glm::dot(p - centre, up_), glm::dot(p - centre, right_));
  };
  std::sort(points.begin(), points.end(),
            [&](const glm::vec3& a, const glm::vec3& b) { return angle(a) < angle(b); });
  return points;
}

std::optional<PlaneRect> CutPlane::boundsInBlock(const Block& block) const {
  const std::vector<glm::vec3> polygon = polygonInBlock(block);
  if (polygon.empty()) return std::nullopt;
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : polygon) {
    const glm::vec2 q = toPlane(p);
    lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  if (hi.x - lo.x <= 0.0f || hi.y - lo.y <= 0.0f) return std::nullopt;
  return PlaneRect{lo, hi};
}

}  // namespace kerf

namespace kerf {

glm::vec3 CutPlaneSetting::normal() const {
  const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return {std::cos(el) * std::cos(az), std::sin(el), -std::cos(el) * std::sin(az)};
}

CutPlaneSetting CutPlaneSetting::fromPlane(const CutPlane& plane) {
  const glm::vec3 n = plane.normal();
  CutPlaneSetting s;
  s.offsetMm = glm::dot(plane.point(), n);
  s.elevationDeg = glm::degrees(std::asin(std::clamp(n.y, -1.0f, 1.0f)));
  s.azimuthDeg =
      (std::abs(n.x) < 1e-7f && std::abs(n.z) < 1e-7f) ? 0.0f : glm::degrees(std::atan2(-n.z, n.x));
  return s;
}

CutPlaneSetting CutPlaneSetting::snapped(float step) const {
  CutPlaneSetting s = *this;
  if (step > 0.0f) {
    s.azimuthDeg = std::round(azimuthDeg / step) * step;
    s.elevationDeg = std::clamp(std::round(elevationDeg / step) * step, -90.0f, 90.0f);
  }
  return s;
}

}  // namespace kerf
