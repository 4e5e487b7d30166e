#include "material/wood_material.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <numbers>

#include "material/noise.hpp"

namespace kerf {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float smoothstep(float a, float b, float x) {
  if (b <= a) return x < a ? 0.0f : 1.0f;
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Wyvill kernel (Liu Sec. 4.6) of a squared distance already divided by the squared influence radius.
float wyvill(float d2) {
  const float w = 1.0f - d2;
  return w > 0.0f ? w * w * w : 0.0f;
}

// Independent sub-seeds for the model's random features, all derived from model.seed.
enum SeedSlot : std::uint32_t {
  kDistortRadial = 1,
  kDistortTangential,
  kRingColor,
  kMottle,
  kFiber,
  kPoreColumn,
  kPoreCell,
  kRayColumn,
  kRayCell
};

}  // namespace

WoodMaterial::WoodMaterial(const WoodParameters& params, const GrowthField& field, const BlockKnots* knots)
    : params_(params),
      field_(field),
      knots_(knots && !knots->empty() ? knots : nullptr),
      seed_(noise::mix(static_cast<std::uint32_t>(params.seed) * 7919u + 13u)) {}

glm::vec3 WoodMaterial::undistort(glm::vec3 p, const Cylindrical& c, glm::vec3* fiberDirection) const {
  const PithAxis& axis = field_.axis();
  const float amplitude = params_.distortionAmplitude;
  if (amplitude <= 0.0f) {
    if (fiberDirection) *fiberDirection = axis.direction;
    return p;
  }
  const float s = params_.distortionScale, along = params_.distortionScale * params_.distortionStretch;
  const glm::vec3 q(c.x / s, c.y / s, c.height / along);
  const glm::vec4 nr = noise::fractal3(q, seed_ + kDistortRadial);
  const glm::vec4 nt = noise::fractal3(q + glm::vec3(31.4f, 27.1f, 8.2f), seed_ + kDistortTangential);
  const glm::vec3 undistorted = p + amplitude * nr.x * c.radial + amplitude * nt.x * c.tangential;
  if (fiberDirection) {
    // Gradients of m_r, m_theta with respect to p (chain rule through the tree frame).
    const auto gradient = [&](const glm::vec4& n) {
      return amplitude * (n.y / s * axis.reference + n.z / s * axis.binormal + n.w / along * axis.direction);
    };
    const glm::vec3 gr = gradient(nr), gt = gradient(nt);
    const float compress = 1.0f / std::sqrt(1.0f + glm::dot(gr, gr) + glm::dot(gt, gt));  // Liu Eq. 3
    const glm::mat3 jacobian =
        glm::mat3(1.0f) + compress * (glm::outerProduct(c.radial, gr) + glm::outerProduct(c.tangential, gt));
    *fiberDirection = glm::normalize(glm::inverse(jacobian) * axis.direction);
  }
  return undistorted;
}

float WoodMaterial::seasonOf(float year) const {
  // Liu Sec. 4.2: a square wave over the year with a controllable early-to-latewood transition.
  const float f = year - params_.ringOffset - std::floor(year - params_.ringOffset);
  const float latewoodStart = 1.0f - params_.latewoodFraction;
  const float rise = smoothstep(latewoodStart * (1.0f - params_.transition), latewoodStart + 1e-4f, f);
  const float fall = 1.0f - smoothstep(1.0f - params_.boundarySoftness, 1.0f, f);
  return rise * fall;
}

float WoodMaterial::poreWeight(const Cylindrical& c, float season) const {
  const float radius = params_.poreRadiusEarly + season * (params_.poreRadiusLate - params_.poreRadiusEarly);
  const float density =
      params_.poreDensityEarly + season * (params_.poreDensityLate - params_.poreDensityEarly);
  if (radius <= 0.0f || density <= 0.0f) return 0.0f;
  // Stratified placement in the cross-section (Liu Sec. 4.6): one candidate pore per cell, placed by a
  // hash of the cell, kept inside its cell so no neighbour cells need checking.
  const float cell = params_.poreCellSize, length = params_.poreLength;
  const float r = std::min(radius, 0.45f * cell);
  const auto i = static_cast<std::int32_t>(std::floor(c.x / cell));
  const auto j = static_cast<std::int32_t>(std::floor(c.y / cell));
  const float stagger = noise::unit(noise::hash(i, j, seed_ + kPoreColumn)) * length;
  const auto k = static_cast<std::int32_t>(std::floor((c.height + stagger) / length));
  const std::uint32_t h = noise::hash(i, j, k, seed_ + kPoreCell);
  if (noise::unit(h) >= density) return 0.0f;
  const float room = 0.5f - r / cell;
  const float cx = (i + 0.5f + room * noise::signedUnit(noise::mix(h ^ 0x9e3779b9U))) * cell;
  const float cy = (j + 0.5f + room * noise::signedUnit(noise::mix(h ^ 0x85ebca6bU))) * cell;
  const float halfLength = 0.5f * length * (0.6f + 0.35f * noise::unit(noise::mix(h ^ 0xc2b2ae35U)));
  const float ch = (k + 0.5f) * length - stagger;
  const float dx = c.x - cx, dy = c.y - cy, dh = (c.height - ch) / halfLength;
  return wyvill((dx * dx + dy * dy) / (r * r) + dh * dh);
}

float WoodMaterial::rayWeight(const Cylindrical& c) const {
  if (params_.rayDensity <= 0.0f || params_.rayOpacity <= 0.0f) return 0.0f;
  // Rays run radially: stratified in angle and height (Liu Sec. 4.6), in radial bands of one ray length.
  const float bandLength = params_.rayLength;
  const auto band = static_cast<std::int32_t>(std::floor(c.radius / bandLength));
  const float bandMiddle = (band + 0.5f) * bandLength;
  const int count = std::max(1, static_cast<int>(std::lround(2.0f * kPi * bandMiddle / params_.raySpacing)));
  const float sector = 2.0f * kPi / count;
  const auto i = std::min(static_cast<std::int32_t>((c.azimuth + kPi) / sector), count - 1);
  const float cellHeight = 3.0f * params_.rayHeight;
  const float stagger = noise::unit(noise::hash(band, i, seed_ + kRayColumn)) * cellHeight;
  const auto k = static_cast<std::int32_t>(std::floor((c.height + stagger) / cellHeight));
  const std::uint32_t h = noise::hash(band, i, k, seed_ + kRayCell);
  if (noise::unit(h) >= params_.rayDensity) return 0.0f;
  const float centerAngle =
      -kPi + (i + 0.5f + 0.3f * noise::signedUnit(noise::mix(h ^ 0x9e3779b9U))) * sector;
  float dAngle = c.azimuth - centerAngle;
  dAngle -= 2.0f * kPi * std::round(dAngle / (2.0f * kPi));
  const float centerHeight =
      (k + 0.5f + 0.15f * noise::signedUnit(noise::mix(h ^ 0x85ebca6bU))) * cellHeight - stagger;
  const float dt = c.radius * dAngle / params_.rayWidth;
  const float dh = (c.height - centerHeight) / params_.rayHeight;
  const float q = c.radius / bandLength - band;  // taper: rays begin and end inside their band
  const float taper = smoothstep(0.0f, 0.12f, q) * (1.0f - smoothstep(0.88f, 1.0f, q));
  return wyvill(dt * dt + dh * dh) * taper;
}

float WoodMaterial::year(glm::vec3 p) const {
  const PithAxis& axis = field_.axis();
  const glm::vec3 u = undistort(p, axis.toCylindrical(p, false), nullptr);
  const Cylindrical c = axis.toCylindrical(u);
  const float stem = field_.evaluate(c);
  return knots_ ? knots_->merge(u, stem, c.radius).time : stem;
}

WoodSample WoodMaterial::evaluate(glm::vec3 p, int faceIndex, bool withFiberDirection) const {
  WoodSample out;
  const PithAxis& axis = field_.axis();
  const Cylindrical distorted = axis.toCylindrical(p, false);  // undistort needs no azimuth
  const glm::vec3 u = undistort(p, distorted, withFiberDirection ? &out.fiberDirection : nullptr);
  const Cylindrical c = axis.toCylindrical(u);

  out.year = field_.evaluate(c);
  float knotDarkness = 0.0f;
  if (knots_) {  // Mokume Sec. 5.2.4 Eq. 7
    const BlockKnotSample k = knots_->merge(u, out.year, c.radius);
    out.year = k.time;
    knotDarkness = k.darkness;
  }
  out.latewood = seasonOf(out.year);
  out.pore = poreWeight(c, out.latewood);
  out.ray = rayWeight(c);

  // Pigment concentration t (Beer's law, Liu Sec. 4.3-4.4).
  float t = out.latewood;
  t += 0.5f * params_.ringColorVariation * noise::value1(out.year, seed_ + kRingColor);
  if (params_.mottleStrength > 0.0f) {
    const float m = params_.mottleScale;
    t += 0.5f * params_.mottleStrength *
         noise::fractal3({c.x / m, c.y / m, c.height / (4.0f * m)}, seed_ + kMottle).x;
  }
  if (params_.fiberStrength > 0.0f) {
    const glm::vec3 q(c.x / params_.fiberWidth, c.y / params_.fiberWidth, c.height / params_.fiberLength);
    t += 0.5f * params_.fiberStrength * noise::value3(q, seed_ + kFiber).x;
  }
  t += params_.poreDarkness * out.pore;
  out.pigment = t;

  const float sap = smoothstep(params_.sapwoodStart - 0.5f * params_.sapwoodTransition,
                               params_.sapwoodStart + 0.5f * params_.sapwoodTransition, out.year);
  const glm::vec3 early =
      glm::max(glm::mix(params_.earlywoodColor, params_.sapwoodEarlywoodColor, sap), glm::vec3(1e-3f));
  const glm::vec3 late =
      glm::max(glm::mix(params_.latewoodColor, params_.sapwoodLatewoodColor, sap), glm::vec3(1e-3f));
  glm::vec3 color = early * glm::pow(late / early, glm::vec3(t));
  color = glm::mix(color, params_.rayColor, params_.rayOpacity * out.ray);
  color -= knotDarkness * params_.knotDarkening;  // Larsson et al. 2022 Sec. 4.3

  static constexpr glm::vec3 WoodParameters::*kTints[6] = {
      &WoodParameters::faceTintA, &WoodParameters::faceTintB, &WoodParameters::faceTintC,
      &WoodParameters::faceTintD, &WoodParameters::faceTintE, &WoodParameters::faceTintF};
  if (faceIndex >= 0 && faceIndex < 6) color *= params_.*kTints[faceIndex];
  out.color = glm::clamp(color, 0.0f, 1.0f);
  return out;
}

}  // namespace kerf
