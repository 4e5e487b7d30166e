#include "field/block_knots.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "util/error.hpp"

namespace kerf {

void validate(const BlockKnot& knot, const std::string& what) {
  const auto finite = [](glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  };
  if (!finite(knot.origin)) throw InputError(what + ": the origin is not a finite point");
  if (!finite(knot.direction) || glm::length(knot.direction) < 1e-6f)
    throw InputError(what + ": the direction must be a finite, non-zero vector");
  if (!(knot.speed > 0.0f && knot.speed < 1.0f))
    throw InputError(what + ": the speed must lie between 0 and 1 (a fraction of the stem's growth speed)");
  if (!(std::abs(knot.taper) <= kMaxKnotTaper))
    throw InputError(what + ": the taper must lie between -" + std::to_string(kMaxKnotTaper) + " and " +
                     std::to_string(kMaxKnotTaper));
  if (!(knot.taperAge > 0.0f && std::isfinite(knot.taperAge)))
    throw InputError(what + ": the taper age must be a positive number of years");
}

BlockKnots::BlockKnots(std::vector<BlockKnot> knots, const KnotSettings& settings, float ringWidthMm)
    : knots_(std::move(knots)), settings_(settings), ringWidth_(ringWidthMm) {
  if (knots_.size() > kMaxBlockKnots)
    throw InputError("the block has " + std::to_string(knots_.size()) + " knots; Kerf takes at most " +
                     std::to_string(kMaxBlockKnots) + " knots in a block");
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    validate(knots_[i], "knots[" + std::to_string(i) + "]");
    knots_[i].direction = glm::normalize(knots_[i].direction);
  }
}

BlockKnotSample BlockKnots::merge(const glm::vec3& p, float stemTime, float stemRadius) const {
  BlockKnotSample out;
  out.time = stemTime;
  const KnotSettings& s = settings_;
  float knotMin = stemTime, sumSmoothing = 0.0f;
  for (const BlockKnot& knot : knots_) {
    const float distance = knotAxisDistance(&knot.origin.x, &knot.direction.x, p);
    const float speed = knotSpeedAt(knot.speed, knot.taper, knot.taperAge, stemTime, maxKnotSpeed(s));
    const KnotTerm<float> term =
        knotTerm(stemTime, distance, stemRadius, speed, ringWidth_, s.knotSmoothStem, s);
    if (!(term.window > 0.0f)) continue;  // out of reach: G unchanged, bit for bit
    knotMin = std::min(knotMin, term.time);
    sumSmoothing += term.smoothing;  // Eq. 6
    if (stemTime > 0.0f) {
      // Sec. 4.3: darker inside the knot, fading over knots.edge_softness of its growth time.
      const float x =
          (term.time / stemTime - (1.0f - s.knotEdgeSoftness)) / std::max(s.knotEdgeSoftness, 1e-4f);
      const float c = std::clamp(x, 0.0f, 1.0f);
      out.darkness = std::max(out.darkness, term.window * (1.0f - c * c * (3.0f - 2.0f * c)));
    }
    ++out.knotsInReach;
  }
  if (out.knotsInReach > 0) out.time = std::max(knotMin + sumSmoothing, 0.0f);
  return out;
}

}  // namespace kerf
