#include "fit/knot_colour_fit.hpp"

#include <algorithm>
#include <cmath>

#include "params/parameter_schema.hpp"
#include "rings/annotations.hpp"

namespace kerf {

namespace {

float median(std::vector<float>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// |p - centre| in units of the outline's radius in that direction (face mm).
float radiusRatio(const KnotOutline& o, glm::vec2 p) {
  const glm::vec2 d = p - o.center;
  const float c = std::cos(o.angleRad), s = std::sin(o.angleRad);
  const float u = (d.x * c + d.y * s) / std::max(o.semiAxesMm.x, 1e-3f);
  const float w = (-d.x * s + d.y * c) / std::max(o.semiAxesMm.y, 1e-3f);
  return std::sqrt(u * u + w * w);
}

}  // namespace

KnotColourFit fitKnotDarkening(const std::array<Image, 6>& photos, const Block& block,
                               const std::vector<KnotOutline>& outlines) {
  KnotColourFit out;
  std::array<std::vector<float>, 3> inside, around;
  for (const KnotOutline& o : outlines) {
    const Image& photo = photos[faceIndex(o.face)];
    if (!o.found || photo.empty() || photo.channels < 3) continue;
    ++out.outlines;
    const glm::ivec2 size(photo.width, photo.height);
    // The pixels of the box around 2x the ellipse only.
    const float reach = 2.0f * o.semiAxesMm.x;
    const glm::vec2 lo = faceMmToImage(block, o.face, o.center - glm::vec2(reach), size);
    const glm::vec2 hi = faceMmToImage(block, o.face, o.center + glm::vec2(reach), size);
    for (int y = std::max(0, static_cast<int>(lo.y)); y < std::min(size.y, static_cast<int>(hi.y) + 1); ++y)
      for (int x = std::max(0, static_cast<int>(lo.x)); x < std::min(size.x, static_cast<int>(hi.x) + 1);
           ++x) {
        const float q = radiusRatio(o, imageToFaceMm(block, o.face, {x + 0.5f, y + 0.5f}, size));
        auto* into = q < 0.6f ? &inside : (q > 1.3f && q < 2.0f) ? &around : nullptr;
        if (!into) continue;
        const float* p = photo.pixel(x, y);
        for (int c = 0; c < 3; ++c) (*into)[c].push_back(p[c]);
      }
  }
  if (inside[0].empty() || around[0].empty()) {
    out.note =
        out.outlines == 0 ? "no knot outline was found on a colour photo" : "the outlines hold no pixels";
    return out;
  }
  const ParamSpec& spec = *findParameter("knots.darkening");
  for (int c = 0; c < 3; ++c) {
    out.knotColour[c] = median(inside[c]);
    out.woodColour[c] = median(around[c]);
    out.darkening[c] = std::clamp(out.woodColour[c] - out.knotColour[c], static_cast<float>(spec.hardMin),
                                  static_cast<float>(spec.hardMax));
  }
  out.fitted = true;
  return out;
}

}  // namespace kerf
