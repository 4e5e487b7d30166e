#include "field/ring_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "util/error.hpp"

namespace kerf {

namespace {

// FNV-1a over raw bytes: a fingerprint, not a security hash.
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void add(float v) { add(&v, sizeof v); }
  void add(int v) { add(&v, sizeof v); }
  void add(glm::vec3 v) { add(&v[0], sizeof(float) * 3); }
};

}  // namespace

std::uint64_t fieldFingerprint(const WoodParameters& params, const GrowthRates& rates,
                               const std::vector<BlockKnot>& knots) {
  Fnv f;
  f.add(params.pithOrigin);
  f.add(params.pithTilt);
  f.add(params.pithAzimuth);
  f.add(params.ringWidth);
  f.add(params.ringOffset);
  f.add(rates.heights);
  f.add(rates.azimuths);
  f.add(rates.radii);
  f.add(rates.heightMin);
  f.add(rates.heightMax);
  f.add(rates.radiusMin);
  f.add(rates.radiusMax);
  f.add(rates.azimuthMin);
  f.add(rates.azimuthMax);
  if (!rates.rates.empty()) f.add(rates.rates.data(), rates.rates.size() * sizeof(float));
  for (const BlockKnot& k : knots) {
    f.add(k.id);
    f.add(k.origin);
    f.add(k.direction);
    f.add(k.speed);
  }
  return f.h;
}

float ringPositionSigmaMm(float referenceYear, float referenceOffset, const std::vector<float>& years,
                          const std::vector<float>& offsets, float ringSpacingMm) {
  if (years.empty()) return 0.0f;
  double sum = 0;
  const float reference = referenceYear - referenceOffset;
  for (std::size_t r = 0; r < years.size(); ++r) {
    float d = (years[r] - offsets[r]) - reference;
    d -= std::floor(d + 0.5f);  // the nearest ring: a replicate may number the years differently
    sum += double(d) * d;
  }
  return static_cast<float>(std::sqrt(sum / double(years.size()))) * ringSpacingMm;
}

float RingUncertainty::at(const Block& block, glm::vec3 pMm) const {
  if (empty()) return 0.0f;
  const glm::vec3 t = glm::clamp((pMm + block.halfSize()) / block.size(), 0.0f, 1.0f);
  const glm::vec3 g = t * glm::vec3(nodes - 1);
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(g)), glm::max(nodes - 2, 0));
  const glm::vec3 f = g - glm::vec3(i0);
  float out = 0;
  for (int c = 0; c < 8; ++c) {
    const glm::ivec3 o(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    const glm::ivec3 n = glm::min(i0 + o, nodes - 1);
    const float w = (o.x ? f.x : 1 - f.x) * (o.y ? f.y : 1 - f.y) * (o.z ? f.z : 1 - f.z);
    out += w * sigmaMm[static_cast<std::size_t>(n.x + nodes.x * (n.y + nodes.y * n.z))];
  }
  return out;
}

float RingUncertainty::quantile(double q) const {
  if (empty()) return 0.0f;
  std::vector<float> v = sigmaMm;
  const auto k = static_cast<std::ptrdiff_t>(std::clamp(q, 0.0, 1.0) * double(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[static_cast<std::size_t>(k)];
}

void RingUncertainty::validate() const {
  if (nodes.x < 2 || nodes.y < 2 || nodes.z < 2 || nodes.x > 256 || nodes.y > 256 || nodes.z > 256)
    throw InputError("ring uncertainty: the grid needs 2 to 256 nodes along each side");
  if (sigmaMm.size() != static_cast<std::size_t>(nodes.x) * nodes.y * nodes.z)
    throw InputError("ring uncertainty: " + std::to_string(sigmaMm.size()) + " values for a grid of " +
                     std::to_string(nodes.x) + " x " + std::to_string(nodes.y) + " x " +
                     std::to_string(nodes.z) + " nodes");
  for (float s : sigmaMm)
    if (!std::isfinite(s) || s < 0) throw InputError("ring uncertainty: a value is negative or not finite");
  if (replicates < 0 || !std::isfinite(calibration) || calibration <= 0)
    throw InputError("ring uncertainty: bad replicate count or calibration");
}

}  // namespace kerf
