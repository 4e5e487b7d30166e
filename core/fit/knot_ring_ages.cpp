#include "fit/knot_ring_ages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rings/annotations.hpp"

namespace kerf {

namespace {

// The field's years (G_k) over each stretch of `count` (from the photo's first to its last dark line on
// that ray), summed.
double fieldYearsOver(const Block& block, const GrowthField& stem, const BlockKnots& knots,
                      const KnotOutline& o, const KnotRingCount& count) {
  const auto yearsAt = [&](glm::vec2 q) {
    const glm::vec3 p = faceMmToBlock(block, o.face, q);
    const Cylindrical c = stem.axis().toCylindrical(p);
    return knots.merge(p, stem.evaluate(c), c.radius).time;
  };
  double sum = 0;
  for (const KnotRingSpan& span : count.spans) {
    const float cr = std::cos(span.angleRad - o.angleRad) / std::max(o.semiAxesMm.x, 1e-3f);
    const float sr = std::sin(span.angleRad - o.angleRad) / std::max(o.semiAxesMm.y, 1e-3f);
    const glm::vec2 edge =
        glm::vec2(std::cos(span.angleRad), std::sin(span.angleRad)) / std::sqrt(cr * cr + sr * sr);
    sum += yearsAt(o.center + span.lastU * edge) - yearsAt(o.center + span.firstU * edge);
  }
  return sum;
}

template <typename... Args>
std::string text(const char* format, Args... args) {
  char buffer[320];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

}  // namespace

std::vector<KnotRingAges> compareKnotRings(const std::array<Image, 6>& photos, const Block& block,
                                           const GrowthField& stem, const BlockKnots& knots,
                                           const std::vector<KnotOutline>& outlines,
                                           const KnotRingCountOptions& options) {
  // Within this share, or the count's two standard deviations, the two agree (the outline's own error
  // and the rings' uneven widths make a few per cent).
  constexpr double kTolerance = 0.15;
  std::vector<KnotRingAges> out;
  for (const BlockKnot& knot : knots.knots()) {
    KnotRingAges ages;
    ages.knot = knot.id;
    std::vector<const KnotRingAgeFace*> found;
    for (const KnotOutline& o : outlines) {
      if (o.knot != knot.id) continue;
      KnotRingAgeFace face;
      face.count = countKnotRings(photos[faceIndex(o.face)], block, o, options);
      if (face.count.found) {
        for (const KnotRingSpan& span : face.count.spans) face.photoRings += span.lines - 1;
        face.fieldYears = fieldYearsOver(block, stem, knots, o, face.count);
      }
      ages.faces.push_back(std::move(face));
    }
    if (ages.faces.empty()) continue;
    for (const KnotRingAgeFace& f : ages.faces)
      if (f.count.found && f.fieldYears > 0) found.push_back(&f);
    ages.counted = !found.empty();
    if (!ages.counted) {
      ages.note = "its own rings are not counted on any photo";
      out.push_back(std::move(ages));
      continue;
    }
    const auto within = [&](double photo, double field, double sigma) {
      return std::abs(photo - field) <= std::max(kTolerance * field, 2.0 * sigma);
    };
    ages.agree = true;
    std::string faces;
    for (const KnotRingAgeFace* f : found) {
      const float field = f->fieldCount();
      ages.agree = ages.agree && within(f->count.rings, field, f->count.sigma);
      if (!faces.empty()) faces += ", ";
      faces += text("%.1f rings on %c where the field has %.1f years", static_cast<double>(f->count.rings),
                    faceLetter(f->count.face), static_cast<double>(field));
    }
    // Between two faces the knot and the stem grew the same layers.
    bool gainsAgree = true;
    std::string gains;
    if (found.size() >= 2) {
      const KnotRingAgeFace& a = *found.front();
      const KnotRingAgeFace& b = *found.back();
      const double photoGain = b.count.rings - a.count.rings;
      const double fieldGain = b.fieldCount() - a.fieldCount();
      const double sigma = std::hypot(a.count.sigma, b.count.sigma);
      gainsAgree = within(photoGain, fieldGain, sigma) || std::abs(photoGain - fieldGain) < 1.0;
      gains = text("; from face to face the knot gains %.1f rings where the field has %.1f years", photoGain,
                   fieldGain);
    }
    ages.agree = ages.agree && gainsAgree;
    ages.note = faces + gains;
    if (ages.agree)
      ages.note += ": the field's years agree with the knot's rings";
    else if (!gainsAgree)
      ages.note +=
          ": the knot's rings and the field's years grow apart between the faces (the ring detection may "
          "count two lines in a year, or the ring width changes there)";
    else
      ages.note += text(
          ": the knot shows %.2f times the field's years (the rings between the pith and the block were %s "
          "than the block's own, so the field's age of the wood here is off)",
          static_cast<double>(found.front()->count.rings / std::max(found.front()->fieldCount(), 1e-3f)),
          found.front()->count.rings < found.front()->fieldCount() ? "wider" : "narrower");
    out.push_back(std::move(ages));
  }
  return out;
}

}  // namespace kerf
