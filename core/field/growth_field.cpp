#include "field/growth_field.hpp"

#include "field/bspline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "params/parameter_schema.hpp"
#include "util/error.hpp"

namespace kerf {

GrowthField::GrowthField(const WoodParameters& params, const GrowthRates& rates)
    : GrowthField(PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth),
                  params.ringWidth, rates) {}

GrowthField::GrowthField(const PithAxis& axis, float ringWidthMm, const GrowthRates& rates)
    : axis_(axis), ringWidth_(ringWidthMm), rates_(rates) {
  rates_.validate();
  if (!(ringWidthMm > 0.0f) || !std::isfinite(ringWidthMm)) {
    throw InputError("the ring width must be a positive number of mm");
  }
  const int nr = rates_.radii;
  radialStep_ = (rates_.radiusMax - rates_.radiusMin) / nr;
  cumulative_.resize(static_cast<std::size_t>(rates_.heights) * rates_.azimuths * (nr + 1));
  const float perMm = 1.0f / ringWidth_;
  for (int ih = 0; ih < rates_.heights; ++ih) {
    for (int ia = 0; ia < rates_.azimuths; ++ia) {
      float* column = &cumulative_[(static_cast<std::size_t>(ih) * rates_.azimuths + ia) * (nr + 1)];
      // From the pith to the first node the first cell's rate applies (Sec. 5.2.1: integrate from the pith).
      double g = rates_.radiusMin * std::max(rates_.at(ih, ia, 0), 0.0f) * perMm;
      column[0] = static_cast<float>(g);
      for (int ir = 0; ir < nr; ++ir) {
        g += radialStep_ * std::max(rates_.at(ih, ia, ir), 0.0f) * perMm;
        column[ir + 1] = static_cast<float>(g);
      }
    }
  }
}

GrowthField::RadialPosition GrowthField::radialPosition(float r) const {
  RadialPosition position;
  position.radius = r;
  if (r <= rates_.radiusMin) {
    position.region = RadialPosition::InsideFirstNode;
    return position;
  }
  const float f = (r - rates_.radiusMin) / radialStep_;
  if (f >= rates_.radii) {
    position.region = RadialPosition::BeyondLastNode;
    return position;
  }
  position.cell = static_cast<int>(f);
  position.t = f - position.cell;
  return position;
}

float GrowthField::radialValue(int ih, int ia, const RadialPosition& p) const {
  switch (p.region) {
    case RadialPosition::InsideFirstNode:
      return rates_.radiusMin > 0.0f ? node(ih, ia, 0) * (p.radius / rates_.radiusMin) : 0.0f;
    case RadialPosition::BeyondLastNode: {
      const int nr = rates_.radii;
      const float lastRate = std::max(rates_.at(ih, ia, nr - 1), 0.0f) / ringWidth_;
      return node(ih, ia, nr) + (p.radius - rates_.radiusMax) * lastRate;
    }
    case RadialPosition::BetweenNodes:
      break;
  }
  return node(ih, ia, p.cell) + p.t * (node(ih, ia, p.cell + 1) - node(ih, ia, p.cell));
}

float GrowthField::evaluate(const Cylindrical& c) const {
  // Height: clamped B-spline over the levels; constant beyond the first/last level.
  const int nh = rates_.heights, na = rates_.azimuths;
  float fh = 0.0f;
  if (nh > 1) {
    fh = (c.height - rates_.heightMin) / (rates_.heightMax - rates_.heightMin) * (nh - 1);
    fh = std::clamp(fh, 0.0f, static_cast<float>(nh - 1));
  }
  const int ih = std::min(static_cast<int>(fh), nh - 1);
  float wh[4];
  bsplineWeights<float>(fh - ih, wh);
  // Azimuth: n_a spokes evenly around the full circle, periodic B-spline.
  float fa = (c.azimuth + std::numbers::pi_v<float>)*(na / (2.0f * std::numbers::pi_v<float>));
  fa = std::clamp(fa, 0.0f, static_cast<float>(na));
  const int ia = static_cast<int>(fa);
  float wa[4];
  bsplineWeights<float>(fa - ia, wa);

  // The four spokes around the point, wrapped around the circle (ia is in [0, na]).
  int spokes[4];
  for (int j = 0; j < 4; ++j) {
    int spoke = ia - 1 + j;
    if (spoke < 0) spoke += na;
    while (spoke >= na) spoke -= na;
    spokes[j] = spoke;
  }
  const RadialPosition radial = radialPosition(c.radius);
  float g = 0.0f;
  for (int i = 0; i < 4; ++i) {
    const int h = std::clamp(ih - 1 + i, 0, nh - 1);
    float row = 0.0f;
    for (int j = 0; j < 4; ++j) row += wa[j] * radialValue(h, spokes[j], radial);
    g += wh[i] * row;
  }
  return g;
}

std::vector<float> ringLevels(float ringOffset, float gMin, float gMax) {
  std::vector<float> levels;
  if (!(gMax >= gMin)) return levels;
  for (double k = std::ceil(gMin - ringOffset); k + ringOffset <= gMax; k += 1.0) {
    levels.push_back(static_cast<float>(k + ringOffset));
  }
  return levels;
}

}  // namespace kerf
