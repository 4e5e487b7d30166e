#include "cut_gizmo.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

namespace kerf {
namespace {

constexpr float kPi = 3.14159265358979f;

float wrapPi(float a) {
  return std::remainder(a, 2.0f * kPi);
}

float wrap180(float deg) {
  float d = std::remainder(deg, 360.0f);
  if (d <= -180.0f) d += 360.0f;
  return d;
}

// Squared distance from p to the segment ab, in pixels.
float segmentDistance2(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  const glm::vec2 d = a + t * ab - p;
  return glm::dot(d, d);
}

}  // namespace

std::vector<glm::vec3> cutPolygon(const Block& block, const CutPlane& plane) {
  return plane.polygonInBlock(block);
}

void CutGizmo::setBlock(const Block& block) {
  block_ = block;
  updatePolygon();
}

void CutGizmo::setSetting(const CutPlaneSetting& setting) {
  if (dragging()) return;
  setting_ = setting;
  updatePolygon();
}

void CutGizmo::updatePolygon() {
  try {
    polygon_ = cutPolygon(block_, setting_.plane());
  } catch (const std::exception&) {  // non-finite angles
    polygon_.clear();
  }
}

glm::vec3 CutGizmo::pivot() const {
  if (dragHandle_ == Handle::AzimuthRing || dragHandle_ == Handle::ElevationRing) return dragPivot_;
  if (polygon_.empty()) return setting_.offsetMm * setting_.normal();
  // Area centroid of the convex polygon (fan from the first corner).
  glm::vec3 sum(0.0f);
  float area = 0.0f;
  for (std::size_t i = 1; i + 1 < polygon_.size(); ++i) {
    const float a = glm::length(glm::cross(polygon_[i] - polygon_[0], polygon_[i + 1] - polygon_[0]));
    sum += a * (polygon_[0] + polygon_[i] + polygon_[i + 1]) / 3.0f;
    area += a;
  }
  if (area <= 0.0f) return polygon_[0];
  return sum / area;
}

float CutGizmo::ringRadius() const {
  // From the block's two smaller sides (a cross-cut's size on a long board), so the rings stay close
  // around the cut surface and do not change while the plane moves.
  glm::vec3 h = block_.halfSize();
  std::sort(&h[0], &h[0] + 3);
  return 0.6f * std::sqrt(h[0] * h[0] + h[1] * h[1]);
}

float CutGizmo::maxOffset(glm::vec3 n) const {
  return glm::dot(glm::abs(n), block_.halfSize());
}

glm::vec3 CutGizmo::ringAxis1(Handle ring) const {
  if (ring == Handle::AzimuthRing) return {1.0f, 0.0f, 0.0f};
  const float az =
      dragHandle_ == Handle::ElevationRing ? startAzimuthRad_ : glm::radians(setting_.azimuthDeg);
  return {std::cos(az), 0.0f, -std::sin(az)};
}

glm::vec3 CutGizmo::ringAxis2(Handle ring) const {
  if (ring == Handle::AzimuthRing) return {0.0f, 0.0f, -1.0f};
  return {0.0f, 1.0f, 0.0f};
}

glm::vec3 CutGizmo::ringPoint(Handle ring, float angle) const {
  return pivot() + ringRadius() * (std::cos(angle) * ringAxis1(ring) + std::sin(angle) * ringAxis2(ring));
}

std::vector<glm::vec3> CutGizmo::ringPolyline(Handle ring, int segments) const {
  std::vector<glm::vec3> points;
  points.reserve(static_cast<std::size_t>(segments) + 1);
  for (int i = 0; i <= segments; ++i) points.push_back(ringPoint(ring, 2.0f * kPi * i / segments));
  return points;
}

CutGizmo::Handle CutGizmo::pick(const OrbitCamera& camera, glm::vec2 px) const {
  if (!meetsBlock()) return Handle::None;
  const float tol2 = kPickTolerancePx * kPickTolerancePx;
  const glm::vec3 centre = pivot();
  const float centreDepth = camera.project(centre).z;
  Handle best = Handle::None;
  float bestScore = std::numeric_limits<float>::max();
  auto consider = [&](Handle h, float d2, bool front) {
    if (d2 > tol2) return;
    const float score = d2 + (front ? 0.0f : 4.0f * tol2);  // front halves win over back halves
    if (score < bestScore) bestScore = score, best = h;
  };
  // Arrow: shaft and tip.
  const glm::vec3 a = camera.project(centre), b = camera.project(arrowTip());
  if (a.z > 0.0f && b.z > 0.0f) {
    consider(Handle::Arrow, segmentDistance2(px, glm::vec2(a), glm::vec2(b)), true);
    const glm::vec2 d = glm::vec2(b) - px;
    consider(Handle::Arrow, std::max(0.0f, glm::dot(d, d) - 9.0f), true);
  }
  for (Handle ring : {Handle::AzimuthRing, Handle::ElevationRing}) {
    const std::vector<glm::vec3> line = ringPolyline(ring, 96);
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const glm::vec3 p = camera.project(line[i]), q = camera.project(line[i + 1]);
      if (p.z <= 0.0f || q.z <= 0.0f) continue;
      const bool front = 0.5f * (p.z + q.z) <= centreDepth + 1e-4f;
      consider(ring, segmentDistance2(px, glm::vec2(p), glm::vec2(q)), front);
    }
  }
  if (best != Handle::None) return best;
  // The surface, where it faces the viewer (else the solid part hides it).
  const Ray ray = camera.rayThrough(px);
  const glm::vec3 n = normal();
  const glm::vec3 planePoint = setting_.offsetMm * n;
  if (glm::dot(camera.eye() - planePoint, n) <= 0.0f) return Handle::None;
  const float denom = glm::dot(ray.direction, n);
  if (std::abs(denom) < 1e-6f) return Handle::None;
  const float t = glm::dot(planePoint - ray.origin, n) / denom;
  if (t <= 0.0f) return Handle::None;
  return block_.contains(ray.at(t), 1e-3f) ? Handle::Surface : Handle::None;
}

float CutGizmo::snapAngle(float deg, bool shiftSnap) {
  if (shiftSnap) return std::round(deg / kSnapStepDeg) * kSnapStepDeg;
  const float principal = std::round(deg / 90.0f) * 90.0f;
  return std::abs(deg - principal) <= kPrincipalSnapDeg ? principal : deg;
}

float CutGizmo::cursorAngle(const OrbitCamera& camera, glm::vec2 px) const {
  const Handle ring = dragHandle_;
  const glm::vec3 e1 = ringAxis1(ring), e2 = ringAxis2(ring), k = glm::cross(e1, e2);
  const Ray ray = camera.rayThrough(px);
  const float denom = glm::dot(ray.direction, k);
  const float t = glm::dot(dragPivot_ - ray.origin, k) / (std::abs(denom) < 1e-6f ? 1e-6f : denom);
  const glm::vec3 q = ray.at(t) - dragPivot_;
  return std::atan2(glm::dot(q, e2), glm::dot(q, e1));
}

bool CutGizmo::beginDrag(Handle handle, const OrbitCamera& camera, glm::vec2 px) {
  if (handle == Handle::None || !meetsBlock()) return false;
  start_ = setting_;
  startPx_ = lastPx_ = px;
  dragPivot_ = pivot();  // before dragHandle_ is set: the centroid of the current surface
  startAzimuthRad_ = glm::radians(setting_.azimuthDeg);
  turned_ = 0.0f;
  const glm::vec3 n = normal();
  if (handle == Handle::Surface || handle == Handle::Arrow) {
    // Grab point: where the ray meets the plane (surface), or the pivot (arrow).
    glm::vec3 grab = dragPivot_;
    if (handle == Handle::Surface) {
      const Ray ray = camera.rayThrough(px);
      const float denom = glm::dot(ray.direction, n);
      if (std::abs(denom) > 1e-6f) grab = ray.at(glm::dot(dragPivot_ - ray.origin, n) / denom);
    }
    // Screen motion of one mm of offset. When the normal points (almost) at the viewer, that motion
    // vanishes: then dragging up pulls the plane towards the viewer instead.
    const glm::vec3 p0 = camera.project(grab), p1 = camera.project(grab + n);
    offsetScreenDir_ = glm::vec2(p1) - glm::vec2(p0);
    const float ppm = camera.pixelsPerMm(grab);
    if (p0.z <= 0.0f || p1.z <= 0.0f || glm::length(offsetScreenDir_) < 0.25f * ppm) {
      const bool towardsViewer = glm::dot(n, camera.forward()) < 0.0f;
      offsetScreenDir_ = glm::vec2(0.0f, towardsViewer ? -ppm : ppm);
    }
  } else {
    const glm::vec3 e1 = ringAxis1(handle), e2 = ringAxis2(handle);
    const glm::vec3 k = glm::cross(e1, e2);
    tangentMode_ = std::abs(glm::dot(camera.rayThrough(px).direction, k)) < 0.2f;
    // Where on the ring the cursor grabbed it (nearest on screen, front half first).
    dragHandle_ = handle;  // ringPoint() of the elevation ring uses the drag's frame
    const float centreDepth = camera.project(dragPivot_).z;
    float best = std::numeric_limits<float>::max();
    for (int i = 0; i < 360; ++i) {
      const float a = glm::radians(static_cast<float>(i));
      const glm::vec3 q = camera.project(ringPoint(handle, a));
      const glm::vec2 d = glm::vec2(q) - px;
      const float score =
          glm::dot(d, d) + (q.z <= centreDepth ? 0.0f : 4.0f * kPickTolerancePx * kPickTolerancePx);
      if (q.z > 0.0f && score < best) best = score, grabAngle_ = a;
    }
  }
  dragHandle_ = handle;
  if ((handle == Handle::AzimuthRing || handle == Handle::ElevationRing) && !tangentMode_)
    lastCursorAngle_ = cursorAngle(camera, px);
  return true;
}

CutPlaneSetting CutGizmo::drag(const OrbitCamera& camera, glm::vec2 px, bool shiftSnap) {
  if (!dragging()) return setting_;
  CutPlaneSetting s = start_;
  if (dragHandle_ == Handle::Surface || dragHandle_ == Handle::Arrow) {
    const float len2 = glm::dot(offsetScreenDir_, offsetScreenDir_);
    float offset = start_.offsetMm + glm::dot(px - startPx_, offsetScreenDir_) / std::max(len2, 1e-12f);
    if (shiftSnap) offset = std::round(offset);
    const float limit = 0.999f * maxOffset(start_.normal());
    s.offsetMm = std::clamp(offset, -limit, limit);
  } else {
    const float startAngle = dragHandle_ == Handle::AzimuthRing ? glm::radians(start_.azimuthDeg)
                                                                : glm::radians(start_.elevationDeg);
    if (tangentMode_) {
      // The ring is seen edge-on: follow the mouse along the ring's screen tangent at the current angle.
      const float current = grabAngle_ + turned_;
      const float eps = 0.01f;
      const glm::vec2 tangent = (glm::vec2(camera.project(ringPoint(dragHandle_, current + eps))) -
                                 glm::vec2(camera.project(ringPoint(dragHandle_, current - eps)))) /
                                (2.0f * eps);
      const float radiusPx = ringRadius() * camera.pixelsPerMm(dragPivot_);
      const float len2 = std::max(glm::dot(tangent, tangent), 0.09f * radiusPx * radiusPx);
      turned_ += glm::dot(px - lastPx_, tangent) / std::max(len2, 1e-6f);
    } else {
      const float angle = cursorAngle(camera, px);
      turned_ += wrapPi(angle - lastCursorAngle_);
      lastCursorAngle_ = angle;
    }
    const float deg = snapAngle(glm::degrees(startAngle + turned_), shiftSnap);
    if (dragHandle_ == Handle::AzimuthRing) {
      s.azimuthDeg = wrap180(deg);
    } else {
      const float a = wrap180(deg);
      if (std::abs(a) <= 90.0f) {
        s.elevationDeg = a, s.azimuthDeg = start_.azimuthDeg;
      } else {  // over the top: the normal now leans the other way
        s.elevationDeg = (a > 0.0f ? 180.0f : -180.0f) - a;
        s.azimuthDeg = wrap180(start_.azimuthDeg + 180.0f);
      }
    }
    s.offsetMm = glm::dot(dragPivot_, s.normal());
  }
  lastPx_ = px;
  setting_ = s;
  updatePolygon();
  return s;
}

void CutGizmo::endDrag() {
  dragHandle_ = Handle::None;
}

CutPlaneSetting CutGizmo::cancelDrag() {
  if (dragging()) {
    setting_ = start_;
    dragHandle_ = Handle::None;
    updatePolygon();
  }
  return setting_;
}

}  // namespace kerf
