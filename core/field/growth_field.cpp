#include "field/growth_field.hpp"

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
  const GridStencil stencil = gridStencil(rates_, c.height, c.azimuth);
  const RadialPosition radial = radialPosition(c.radius);
  float g = 0.0f;
  for (int i = 0; i < 4; ++i) {
    float row = 0.0f;
    for (int j = 0; j < 4; ++j)
      row += stencil.spokeWeights[j] * radialValue(stencil.heights[i], stencil.spokes[j], radial);
    g += stencil.heightWeights[i] * row;
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
