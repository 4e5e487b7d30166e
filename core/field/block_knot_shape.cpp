#include "field/block_knot_shape.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace kerf {
namespace {

constexpr float kDeg = 180.0f / std::numbers::pi_v<float>;

// The parameter range [tIn, tOut] of the knot's half-line inside the block; empty when tIn > tOut.
std::pair<float, float> runThroughBlock(const BlockKnot& knot, const Block& block) {
  const glm::vec3 half = block.halfSize();
  const glm::vec3 d = glm::normalize(knot.direction);
  float tIn = 0.0f, tOut = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12f) {
      if (std::abs(knot.origin[a]) > half[a]) return {1.0f, 0.0f};
      continue;
    }
    const float t0 = (-half[a] - knot.origin[a]) / d[a], t1 = (half[a] - knot.origin[a]) / d[a];
    tIn = std::max(tIn, std::min(t0, t1));
    tOut = std::min(tOut, std::max(t0, t1));
  }
  return {tIn, tOut};
}

FaceId faceAt(const Block& block, glm::vec3 p) {
  FaceId best = FaceId::A;
  float bestGap = std::numeric_limits<float>::infinity();
  for (FaceId face : kAllFaces) {
    const FaceFrame frame = block.face(face);
    const float gap = std::abs(glm::dot(p - frame.center, frame.normal));
    if (gap < bestGap) bestGap = gap, best = face;
  }
  return best;
}

}  // namespace

BlockKnotShape describeBlockKnot(const BlockKnot& knot, const PithAxis& pith) {
  const glm::vec3 d = glm::normalize(knot.direction);
  BlockKnotShape s;
  s.heightMm = glm::dot(knot.origin, pith.direction);
  s.angleToPithDeg = std::acos(std::clamp(glm::dot(d, pith.direction), -1.0f, 1.0f)) * kDeg;
  const float x = glm::dot(d, pith.reference), y = glm::dot(d, pith.binormal);
  s.aroundDeg = std::hypot(x, y) > 1e-6f ? std::atan2(y, x) * kDeg : 0.0f;
  s.speed = knot.speed;
  s.taper = knot.taper;
  s.deathYears = knot.deathTime;
  return s;
}

BlockKnot reshapeBlockKnot(BlockKnot knot, const BlockKnotShape& shape, const PithAxis& pith) {
  const BlockKnotShape before = describeBlockKnot(knot, pith);
  if (shape.heightMm != before.heightMm) knot.origin += (shape.heightMm - before.heightMm) * pith.direction;
  if (shape.angleToPithDeg != before.angleToPithDeg || shape.aroundDeg != before.aroundDeg) {
    const float a = shape.angleToPithDeg / kDeg, t = shape.aroundDeg / kDeg;
    const glm::vec3 radial = std::cos(t) * pith.reference + std::sin(t) * pith.binormal;
    knot.direction = glm::normalize(std::cos(a) * pith.direction + std::sin(a) * radial);
  }
  knot.speed = shape.speed;
  knot.taper = shape.taper;
  knot.deathTime = shape.deathYears;
  return knot;
}

std::vector<KnotCrossing> knotCrossings(const BlockKnot& knot, const Block& block, const GrowthField& field,
                                        const KnotSettings& settings) {
  const auto [tIn, tOut] = runThroughBlock(knot, block);
  std::vector<KnotCrossing> out;
  if (!(tIn <= tOut) || !std::isfinite(tOut)) return out;
  const glm::vec3 d = glm::normalize(knot.direction);
  const glm::vec3 half = block.halfSize();
  const auto onSurface = [&](glm::vec3 p) {
    for (int a = 0; a < 3; ++a)
      if (std::abs(std::abs(p[a]) - half[a]) < 1e-3f * std::max(1.0f, half[a])) return true;
    return false;
  };
  for (float t : {tIn, tOut}) {
    const glm::vec3 p = knot.origin + t * d;
    if (!onSurface(p)) continue;  // the knot starts inside the block
    KnotCrossing c;
    c.face = faceAt(block, p);
    c.point = p;
    c.stemYears = field.evaluate(p);
    const float growing = std::min(c.stemYears, knot.deathTime);
    const float v = knotSpeedAt(knot.speed, knot.taper, knot.taperAge, growing, maxKnotSpeed(settings));
    c.diameterMm = 2.0f * v * field.ringWidth() * growing;
    out.push_back(c);
  }
  return out;
}

float middleStemYears(const BlockKnot& knot, const Block& block, const GrowthField& field) {
  const auto [tIn, tOut] = runThroughBlock(knot, block);
  const glm::vec3 p = tIn <= tOut && std::isfinite(tOut)
                          ? knot.origin + 0.5f * (tIn + tOut) * glm::normalize(knot.direction)
                          : glm::vec3(0.0f);
  return std::max(1.0f, field.evaluate(p));
}

}  // namespace kerf
