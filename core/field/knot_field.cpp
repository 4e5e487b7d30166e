#include "field/knot_field.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <numbers>

#include "model/knot_check_kernels.hpp"
#include "model/noise.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTwoPi = 2.0f * kPi;

inline float smoothstep01(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x * x * (3.0f - 2.0f * x);
}

// Smooth value noise in [-1, 1] on a lattice that wraps after `period` cells in u (periodic around a
// knot's axis, Sec. 4.1 "periodic Perlin noise") and is open in v.
float periodicNoise(float u, float v, int period, std::uint32_t seed) {
  const float fu = std::floor(u), fv = std::floor(v);
  int iu = static_cast<int>(fu) % period;
  if (iu < 0) iu += period;
  const int iu1 = iu + 1 == period ? 0 : iu + 1;
  const auto iv = static_cast<std::int32_t>(fv);
  const float a = noise::fade(u - fu), b = noise::fade(v - fv);
  const float n00 = noise::signedUnit(noise::hash(iu, iv, seed)),
              n10 = noise::signedUnit(noise::hash(iu1, iv, seed));
  const float n01 = noise::signedUnit(noise::hash(iu, iv + 1, seed)),
              n11 = noise::signedUnit(noise::hash(iu1, iv + 1, seed));
  const float lower = n00 + a * (n10 - n00), upper = n01 + a * (n11 - n01);
  return lower + b * (upper - lower);
}

// Two octaves, |result| <= 1; beta in radians around the knot axis, v along the knot.
float knotNoise(float beta, float v, std::uint32_t seed, int p1, int p2) {
  const float turns = beta * (1.0f / kTwoPi);
  const float u = turns - std::floor(turns);
  return 0.6f * periodicNoise(u * static_cast<float>(p1), v * 4.0f, p1, seed) +
         0.4f * periodicNoise(u * static_cast<float>(p2), v * 9.0f, p2, seed ^ 0x9e3779b9U);
}

constexpr int kNoiseAngles = 64, kNoiseTimes = 64;
constexpr float kNoiseMaxTime = 1.5f;  // stem times beyond it use the last row
static_assert(kNoiseAngles == KnotField::kNoiseTableAngles && kNoiseTimes == KnotField::kNoiseTableTimes &&
              kNoiseMaxTime == KnotField::kNoiseTableMaxTime);

}  // namespace

KnotSettings KnotSettings::fromParameters(const WoodParameters& p) {
  KnotSettings s;
#define KERF_PARAM(name, ...) s.name = p.name;
#include "params/knot_parameters.def"
#undef KERF_PARAM
  return s;
}

// Eq. 2 in the form m (1 + (m/M)^k)^(-1/k), m = min, M = max: algebraically the same, and free of
// overflow for large k and of 0/0 at the pith (t = 0).
float powerSmoothMin(float a, float b, float k) {
  if (a > 0.0f && b > 0.0f && !std::isfinite(std::max(a, b))) return std::min(a, b);
  return powerSmoothMinOf(a, b, k);
}

// Eq. 3.
float smoothingAmount(float a, float b, float k) {
  return powerSmoothMin(a, b, k) - std::min(a, b);
}

// Sec. 4.2.1: an algebraic sigmoid of t_delta = t_s - T_b (positive inside the knot).
float adaptiveK(float stemTime, float knotTime, const KnotSettings& s) {
  const float delta = stemTime - knotTime;
  const float sig = delta / (s.knotSmoothTransition + std::abs(delta));
  return 0.5f * (s.knotSmoothKnot + s.knotSmoothStem) + 0.5f * (s.knotSmoothKnot - s.knotSmoothStem) * sig;
}

// Sec. 4.2.2.
float deadKnotFactor(float tau, float beta, const KnotSettings& s) {
  return deadKnotFactorOf(tau, beta, s);
}

float knotWindow(float ratio, const KnotSettings& s) {
  return knotWindowOf(ratio, s.knotReachStart, s.knotReachEnd);
}

WoodColorMap woodColorMapFromParameters(const WoodParameters& p, float radiusMm) {
  WoodColorMap map;
  const int n = 4096;
  const float years = std::max(radiusMm / p.ringWidth, 1.0f);
  map.colors.resize(n);
  for (int i = 0; i < n; ++i) {
    const float year = years * static_cast<float>(i) / static_cast<float>(n - 1);
    const float s = year - std::floor(year);
    // Earlywood to latewood within the year (Liu 4.2), sharp drop at the ring boundary.
    const float lateStart = 1.0f - p.latewoodFraction;
    const float ramp = std::max(p.transition * lateStart, 1e-3f);
    const float season = smoothstep01((s - (lateStart - ramp)) / ramp) *
                         (1.0f - smoothstep01((s - (1.0f - p.boundarySoftness)) / p.boundarySoftness));
    const float sap = smoothstep01((year - p.sapwoodStart) / p.sapwoodTransition + 0.5f);
    const glm::vec3 early = p.earlywoodColor + sap * (p.sapwoodEarlywoodColor - p.earlywoodColor);
    const glm::vec3 late = p.latewoodColor + sap * (p.sapwoodLatewoodColor - p.latewoodColor);
    map.colors[i] = early + season * (late - early);
  }
  return map;
}

KnotField::KnotField(LogModel log, const KnotSettings& settings) : log_(std::move(log)), settings_(settings) {
  validate(log_);
  if (!(settings_.knotReachEnd > 0.0f) || !(settings_.knotReachStart > 0.0f)) {
    throw InputError("knots.reach_start and knots.reach_end must be > 0");
  }
  allKnots_.resize(log_.knots.size());
  for (std::size_t i = 0; i < allKnots_.size(); ++i) allKnots_[i] = static_cast<int>(i);
  const std::size_t cells = static_cast<std::size_t>(kNoiseAngles) * kNoiseTimes;
  speedNoise_.resize(cells * log_.knots.size());
  outlineNoise_.resize(cells * log_.knots.size());
  // One knot per task: the tables of the spruce log's 108 knots took a tenth of a whole render-board run.
  parallelRows(static_cast<int>(log_.knots.size()), [&](int knot) {
    const auto k = static_cast<std::size_t>(knot);
    const auto seed = static_cast<std::uint32_t>(k) * 2654435761U + 17U;
    for (int j = 0; j < kNoiseTimes; ++j) {
      const float t = kNoiseMaxTime * static_cast<float>(j) / static_cast<float>(kNoiseTimes - 1);
      for (int i = 0; i < kNoiseAngles; ++i) {
        const float beta = kTwoPi * static_cast<float>(i) / static_cast<float>(kNoiseAngles);
        const std::size_t at = k * cells + static_cast<std::size_t>(j) * kNoiseAngles + i;
        speedNoise_[at] = knotNoise(beta, t, seed, 3, 7);
        outlineNoise_[at] = knotNoise(beta, t, seed ^ 0x5bd1e995U, 5, 13);
      }
    }
  });
}

float KnotField::noiseAt(const std::vector<float>& table, int knot, float beta, float stemTime) const {
  float u = beta * (static_cast<float>(kNoiseAngles) / kTwoPi);
  u -= std::floor(u * (1.0f / kNoiseAngles)) * static_cast<float>(kNoiseAngles);
  int i = static_cast<int>(u);
  const float fu = u - static_cast<float>(i);
  if (i >= kNoiseAngles) i = 0;
  const int i1 = i + 1 == kNoiseAngles ? 0 : i + 1;
  const float v = std::clamp(stemTime * (static_cast<float>(kNoiseTimes - 1) / kNoiseMaxTime), 0.0f,
                             static_cast<float>(kNoiseTimes - 1));
  const int j = std::min(static_cast<int>(v), kNoiseTimes - 2);
  const float fv = v - static_cast<float>(j);
  const float* row = &table[static_cast<std::size_t>(knot) * kNoiseAngles * kNoiseTimes +
                            static_cast<std::size_t>(j) * kNoiseAngles];
  const float lower = row[i] + fu * (row[i1] - row[i]);
  const float upper = row[i + kNoiseAngles] + fu * (row[i1 + kNoiseAngles] - row[i + kNoiseAngles]);
  return lower + fv * (upper - lower);
}

KnotFieldSample KnotField::evaluate(const glm::vec3& p, std::span<const int> knots) const {
  const KnotSettings& s = settings_;
  const Stem& stem = log_.stem;
  KnotFieldSample out;
  // Stem (Eq. 1): the pseudo-nearest pith point is the one at the same height.
  const glm::vec2 pith = stem.pithAt(p.z);
  const float qx = p.x - pith.x, qy = p.y - pith.y;
  const float ds = std::sqrt(qx * qx + qy * qy);
  const float theta = std::atan2(qy, qx);
  const float rs = stem.radiusAt(p.z, theta);
  const float ts = ds / rs;
  out.stemTime = ts;
  out.time = ts;
  if (ds < 1e-3f) return out;

  const float reach = s.knotReachEnd * ds;
  const float reach2 = reach * reach;
  const float maxFraction = 0.9f * std::min(s.knotReachStart, s.knotReachEnd);
  float knotMin = 1e30f, sumDelta = 0.0f;
  for (const int index : knots) {
    const Knot& knot = log_.knots[index];
    // Knot (Eq. 1): the pseudo-nearest skeleton point is the one at the same distance d_s from the pith.
    const float zb = knot.heightAt(ds);
    const float dz = p.z - zb;
    if (std::abs(dz) >= reach) continue;
    const float dTheta = theta - knot.azimuthAt(ds);
    const float along = ds * std::sin(dTheta);            // along the horizontal tangent of the knot
    const float radial = ds * (std::cos(dTheta) - 1.0f);  // towards the pith
    const float db2 = along * along + radial * radial + dz * dz;
    if (db2 >= reach2) continue;  // out of reach: exactly no contribution (what cull() relies on)
    const float db = std::sqrt(db2);
    const float ratio = db / ds;
    const float window = knotWindow(ratio, s);
    const float beta = std::atan2(dz, along);  // around the knot axis: 0 = side, pi/2 = above
    // Speed of the knot's growth, a fraction of the stem's (Sec. 4.1), with periodic noise around its axis.
    float fraction = (s.knotSpeed - s.knotSpeedDecline * std::sqrt(ts)) *
                     (1.0f + s.knotSpeedNoise * noiseAt(speedNoise_, index, beta, ts));
    fraction = std::clamp(fraction, 0.01f, maxFraction);  // keeps T_b > t_s beyond reach_start
    float tb = db / (fraction * rs);
    const float k = adaptiveK(ts, tb, s);  // Sec. 4.2.1
    const float tDeath = knot.deathDistance / rs;
    const float tAlive = powerSmoothMin(ts, tb, k);
    float delta = tAlive - std::min(ts, tb);  // Eq. 3
    // Sec. 4.3: a dark outline of noisy width where the knot's surface froze at death (T_b = t_death), on
    // the wood that grew after it.
    if (ts > tDeath && ratio < s.knotReachStart) {
      const float width =
          s.knotOutlineWidth * (1.0f + s.knotOutlineNoise * noiseAt(outlineNoise_, index, beta, ts));
      if (inDeadKnotOutline(ts, tb, tDeath, width)) out.outline = true;
    }
    // Checks (Kerf's own, model/kernels/knot_checks.glsl) in the knot's section, frozen at its death.
    const float section = fraction * rs * std::min(ts, tDeath);
    out.checks = std::min(out.checks, knotCheckShade(index, db, section, beta, ds, ts, tDeath, s.knotChecks));
    // Dead (Eq. 5, Sec. 4.2.2): the knot stops thickening, its union with the stem sharpens and inverts.
    applyKnotDeath(ts, tAlive, tDeath, k, beta, s, tb, delta);
    // Sec. 4.3: a dead knot, where the stem grew on after its death, is darker.
    out.deadShade = std::max(out.deadShade, deadKnotShade(ts, tb, tDeath, s));
    knotMin = std::min(knotMin, tb);
    sumDelta += window * delta;  // Eq. 6, the sum of the pairwise smoothing amounts
    const float inside =
        1.0f - smoothstep01((tb / ts - (1.0f - s.knotEdgeSoftness)) / std::max(s.knotEdgeSoftness, 1e-4f));
    out.darkness = std::max(out.darkness, window * inside);
    ++out.knotsInReach;
  }
  out.knotTime = knotMin;
  if (out.knotsInReach > 0) {
    // Inside a knot its own rings stay undistorted by the fillets (as in the authors' shader; not one of
    // the paper's equations): the sum fades out with the depth inside the nearest knot.
    const float depth = smoothstep01(std::max(ts - knotMin, 0.0f) / ts);
    out.time = std::max(std::min(ts, knotMin) + sumDelta * (1.0f - depth), 0.0f);  // Eq. 6
  }
  return out;
}

glm::vec3 KnotField::color(const KnotFieldSample& sample, const WoodColorMap& map) const {
  glm::vec3 c = map.at(sample.time);
  c -= (sample.darkness + sample.deadShade) * settings_.knotDarkening;  // Sec. 4.3
  if (sample.outline) c *= settings_.knotOutlineShade;
  c *= sample.checks;
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

void KnotField::cull(const glm::vec3& lo, const glm::vec3& hi, std::span<const int> candidates,
                     std::vector<int>& out) const {
  const Stem& stem = log_.stem;
  // Points of the box relative to the pith at their own height: a box around the pith-centred x, y.
  glm::vec2 pithLo, pithHi;
  stem.pithRange(lo.z, hi.z, pithLo, pithHi);
  const glm::vec2 qLo = glm::vec2(lo.x, lo.y) - pithHi, qHi = glm::vec2(hi.x, hi.y) - pithLo;
  const float nx = std::max({qLo.x, 0.0f, -qHi.x}), ny = std::max({qLo.y, 0.0f, -qHi.y});
  const float dMin = std::sqrt(nx * nx + ny * ny);
  const float fx = std::max(std::abs(qLo.x), std::abs(qHi.x)),
              fy = std::max(std::abs(qLo.y), std::abs(qHi.y));
  const float dMax = std::sqrt(fx * fx + fy * fy);
  const float reach = settings_.knotReachEnd * dMax;  // no knot term survives d_b >= reach_end x d_s
  // Azimuths the box covers: an interval around its centre's azimuth (all of them if it holds the pith).
  float thetaCentre = 0.0f, thetaHalf = kPi;
  if (dMin > 0.0f) {
    thetaCentre = std::atan2(0.5f * (qLo.y + qHi.y), 0.5f * (qLo.x + qHi.x));
    thetaHalf = 0.0f;
    for (int c = 0; c < 4; ++c) {
      const float x = (c & 1) ? qHi.x : qLo.x, y = (c & 2) ? qHi.y : qLo.y;
      float d = std::atan2(y, x) - thetaCentre;
      d -= kTwoPi * std::round(d / kTwoPi);
      thetaHalf = std::max(thetaHalf, std::abs(d));
    }
  }
  for (const int index : candidates) {
    const Knot& knot = log_.knots[index];
    float zLo, zHi;
    knot.heightRange(dMin, dMax, zLo, zHi);
    const float gapZ = std::max({zLo - hi.z, lo.z - zHi, 0.0f});
    float gapH = 0.0f;
    if (thetaHalf < kPi) {
      float wLo, wHi;
      knot.azimuthRange(dMin, dMax, wLo, wHi);
      float d = 0.5f * (wLo + wHi) - thetaCentre;
      d -= kTwoPi * std::round(d / kTwoPi);
      const float gap = std::abs(d) - thetaHalf - 0.5f * (wHi - wLo);
      // Two points at distance >= dMin from the pith, azimuths `gap` apart: chord >= 2 dMin sin(gap / 2).
      if (gap > 0.0f) gapH = 2.0f * dMin * std::sin(0.5f * std::min(gap, kPi));
    }
    // A small margin for float rounding in the bound: it must never cull a knot that reaches.
    if (gapZ * gapZ + gapH * gapH < reach * reach * 1.0001f + 1e-6f) out.push_back(index);
  }
}

}  // namespace kerf
