#include "field/growth_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "params/parameter_schema.hpp"
#include "util/error.hpp"

namespace kerf {

GrowthField::GrowthField(const WoodParameters& params, const GrowthRates& rates)
    : GrowthField(PithAxis::fromAngles(params.pithOrigin, params.pithTilt, params.pithAzimuth), params.ringWidth,
                  rates) {}

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

float GrowthField::radialValue(int ih, int ia, float r) const {
  const int nr = rates_.radii;
  if (r <= rates_.radiusMin) {
    return rates_.radiusMin > 0.0f ? node(ih, ia, 0) * (r / rates_.radiusMin) : 0.0f;
  }
  const float f = (r - rates_.radiusMin) / radialStep_;
  if (f >= nr) {
    const float lastRate = std::max(rates_.at(ih, ia, nr - 1), 0.0f) / ringWidth_;
    return node(ih, ia, nr) + (r - rates_.radiusMax) * lastRate;
  }
  const int ir = static_cast<int>(f);
  const float t = f - ir;
  return node(ih, ia, ir) + t * (node(ih, ia, ir + 1) - node(ih, ia, ir));
}

float GrowthField::evaluate(const Cylindrical& c) const {
  // Height: linear between levels, constant beyond the first/last level.
  float fh = 0.0f;
  if (rates_.heights > 1) {
    fh = (c.height - rates_.heightMin) / (rates_.heightMax - rates_.heightMin) * (rates_.heights - 1);
    fh = std::clamp(fh, 0.0f, static_cast<float>(rates_.heights - 1));
  }
  const int ih0 = std::min(static_cast<int>(fh), rates_.heights - 1);
  const int ih1 = std::min(ih0 + 1, rates_.heights - 1);
  const float th = fh - ih0;
  // Azimuth: n_a spokes evenly around the full circle, periodic.
  float fa = (c.azimuth + std::numbers::pi_v<float>) * (rates_.azimuths / (2.0f * std::numbers::pi_v<float>));
  fa = std::clamp(fa, 0.0f, static_cast<float>(rates_.azimuths));
  int ia0 = static_cast<int>(fa);
  const float ta = fa - ia0;
  ia0 %= rates_.azimuths;
  const int ia1 = (ia0 + 1) % rates_.azimuths;

  const float g00 = radialValue(ih0, ia0, c.radius), g01 = radialValue(ih0, ia1, c.radius);
  const float g10 = radialValue(ih1, ia0, c.radius), g11 = radialValue(ih1, ia1, c.radius);
  const float g0 = g00 + ta * (g01 - g00), g1 = g10 + ta * (g11 - g10);
  return g0 + th * (g1 - g0);
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
