#include "field/block_knots.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "model/knot_check_kernels.hpp"
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
  if (!(knot.deathTime > 0.0f))  // infinity passes: alive
    throw InputError(what +
                     ": the death time must be a positive number of years from the pith (or none: "
                     "an alive knot)");
}

void knotFrame(const glm::vec3& direction, const glm::vec3& pithDirection, glm::vec3& up, glm::vec3& side) {
  up = pithDirection - glm::dot(pithDirection, direction) * direction;
  // A knot along the pith axis has no "above": any perpendicular will do (such a knot is refused by the fit).
  if (glm::length(up) < 1e-4f) up = std::abs(direction.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  up = glm::normalize(up - glm::dot(up, direction) * direction);
  side = glm::cross(direction, up);
}

BlockKnots::BlockKnots(std::vector<BlockKnot> knots, const KnotSettings& settings, float ringWidthMm,
                       glm::vec3 pithDirection)
    : knots_(std::move(knots)), settings_(settings), ringWidth_(ringWidthMm) {
  if (knots_.size() > kMaxBlockKnots)
    throw InputError("the block has " + std::to_string(knots_.size()) + " knots; Kerf takes at most " +
                     std::to_string(kMaxBlockKnots) + " knots in a block");
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    validate(knots_[i], "knots[" + std::to_string(i) + "]");
    knots_[i].direction = glm::normalize(knots_[i].direction);
  }
  if (!(settings_.knotStemRadius > 0.0f)) throw InputError("knots.stem_radius must be > 0");
  up_.resize(knots_.size());
  side_.resize(knots_.size());
  for (std::size_t i = 0; i < knots_.size(); ++i)
    knotFrame(knots_[i].direction, glm::normalize(pithDirection), up_[i], side_[i]);
}

BlockKnotSample BlockKnots::merge(const glm::vec3& p, float stemTime, float stemRadius) const {
  BlockKnotSample out;
  out.time = stemTime;
  const KnotSettings& s = settings_;
  float knotMin = stemTime, sumSmoothing = 0.0f, deadShade = 0.0f, checks = 1.0f;
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    const BlockKnot& knot = knots_[i];
    const float distance = knotAxisDistance(&knot.origin.x, &knot.direction.x, p);
    // A dead knot keeps the section of its death: its speed is the one it had then.
    const float growing = std::min(stemTime, knot.deathTime);
    const float speed = knotSpeedAt(knot.speed, knot.taper, knot.taperAge, growing, maxKnotSpeed(s));
    KnotDeathAt<float> death{knot.deathTime, 0.0f};
    const float rel[3] = {p.x - knot.origin.x, p.y - knot.origin.y, p.z - knot.origin.z};
    if (knot.dead()) death.beta = knotAngleOf(rel, &knot.direction.x, up_[i], side_[i]);
    const KnotTerm<float> term =
        knotTerm(stemTime, distance, stemRadius, speed, ringWidth_, s.knotSmoothStem, s, death);
    if (!(term.window > 0.0f)) continue;  // out of reach: G unchanged, bit for bit
    knotMin = std::min(knotMin, term.time);
    sumSmoothing += term.smoothing;  // Eq. 6
    // Checks (Kerf's own, model/kernels/knot_checks.glsl) in the knot's section (mm), frozen at its death.
    const float section = speed * ringWidth_ * growing;
    if (s.knotChecks > 0.0f && distance < section) {
      const glm::vec3& u = knot.direction;
      const float along = rel[0] * u.x + rel[1] * u.y + rel[2] * u.z;
      const float beta = knot.dead() ? death.beta : knotAngleOf(rel, &u.x, up_[i], side_[i]);
      const float c = stemTimePerYear(ringWidth_, s);
      checks = std::min(checks, knotCheckShade(knot.id, distance, section, beta, along, stemTime * c,
                                               knot.deathTime * c, s.knotChecks));
    }
    if (knot.dead()) {
      // Sec. 4.3 as the log: the bark ring where the knot's surface froze, the dead wood darker.
      const float c = stemTimePerYear(ringWidth_, s);
      const float ts = stemTime * c, tDeath = knot.deathTime * c;
      const float frozen = distance / (speed * ringWidth_) * c;  // the knot time before Eq. 5
      if (distance < s.knotReachStart * stemRadius &&
          inDeadKnotOutline(ts, frozen, tDeath, s.knotOutlineWidth))
        out.shade = s.knotOutlineShade;
      deadShade = std::max(deadShade, deadKnotShade(ts, term.time * c, tDeath, s));
    }
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
  out.darkness += deadShade;  // the log's colour: (darkness + dead shade) x knots.darkening
  out.shade *= checks;
  return out;
}

}  // namespace kerf
