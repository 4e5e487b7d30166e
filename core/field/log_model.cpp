#include "field/log_model.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "util/error.hpp"

namespace kerf {

namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// Position of x on a regular grid of `count` samples with spacing `step`: index i and fraction f.
inline void gridPosition(float x, float step, int count, int& i, float& f) {
  const float u = std::clamp(x / step, 0.0f, static_cast<float>(count - 1));
  i = std::min(static_cast<int>(u), std::max(count - 2, 0));
  f = u - static_cast<float>(i);
}

// Min and max of a piecewise-linear table (spacing `step`) over [x0, x1].
void tableRange(const std::vector<float>& v, float step, float x0, float x1, float& lo, float& hi) {
  const int n = static_cast<int>(v.size());
  auto at = [&](float x) {
    int i;
    float f;
    gridPosition(x, step, n, i, f);
    return n == 1 ? v[0] : v[i] + f * (v[i + 1] - v[i]);
  };
  lo = std::min(at(x0), at(x1));
  hi = std::max(at(x0), at(x1));
  const int j0 = std::max(0, static_cast<int>(std::ceil(x0 / step)));
  const int j1 = std::min(n - 1, static_cast<int>(std::floor(x1 / step)));
  for (int j = j0; j <= j1; ++j) {
    lo = std::min(lo, v[j]);
    hi = std::max(hi, v[j]);
  }
}

}  // namespace

glm::vec2 Stem::pithAt(float z) const {
  if (pith.size() == 1) return pith[0];
  int i;
  float f;
  gridPosition(z, heightStep, slices(), i, f);
  return pith[i] + f * (pith[i + 1] - pith[i]);
}

float Stem::radiusAt(float z, float azimuth) const {
  int i;
  float f;
  gridPosition(z, heightStep, slices(), i, f);
  const int i1 = slices() > 1 ? i + 1 : i;
  float a = azimuth * (static_cast<float>(azimuths) / kTwoPi);
  a -= std::floor(a / static_cast<float>(azimuths)) * static_cast<float>(azimuths);
  int j = static_cast<int>(a);
  const float g = a - static_cast<float>(j);
  if (j >= azimuths) j = 0;
  const int j1 = j + 1 == azimuths ? 0 : j + 1;
  const float* r0 = &radii[static_cast<std::size_t>(i) * azimuths];
  const float* r1 = &radii[static_cast<std::size_t>(i1) * azimuths];
  const float lower = r0[j] + g * (r0[j1] - r0[j]);
  const float upper = r1[j] + g * (r1[j1] - r1[j]);
  return lower + f * (upper - lower);
}

float Stem::minRadius() const {
  return radii.empty() ? 0.0f : *std::min_element(radii.begin(), radii.end());
}

float Stem::maxRadius() const {
  return radii.empty() ? 0.0f : *std::max_element(radii.begin(), radii.end());
}

void Stem::pithRange(float z0, float z1, glm::vec2& lo, glm::vec2& hi) const {
  const glm::vec2 a = pithAt(z0), b = pithAt(z1);
  lo = glm::min(a, b);
  hi = glm::max(a, b);
  const int j0 = std::max(0, static_cast<int>(std::ceil(z0 / heightStep)));
  const int j1 = std::min(slices() - 1, static_cast<int>(std::floor(z1 / heightStep)));
  for (int j = j0; j <= j1; ++j) {
    lo = glm::min(lo, pith[j]);
    hi = glm::max(hi, pith[j]);
  }
}

float Knot::heightAt(float d) const {
  if (heights.size() == 1) return heights[0];
  int i;
  float f;
  gridPosition(d, distanceStep, samples(), i, f);
  return heights[i] + f * (heights[i + 1] - heights[i]);
}

float Knot::azimuthAt(float d) const {
  if (azimuths.size() == 1) return azimuths[0];
  int i;
  float f;
  gridPosition(d, distanceStep, samples(), i, f);
  return azimuths[i] + f * (azimuths[i + 1] - azimuths[i]);
}

void Knot::heightRange(float d0, float d1, float& lo, float& hi) const {
  tableRange(heights, distanceStep, d0, d1, lo, hi);
}

void Knot::azimuthRange(float d0, float d1, float& lo, float& hi) const {
  tableRange(azimuths, distanceStep, d0, d1, lo, hi);
}

glm::vec3 WoodColorMap::at(float t) const {
  if (colors.empty()) return glm::vec3(0.5f);
  const float u = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(colors.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(u), colors.size() - 1);
  const std::size_t j = std::min(i + 1, colors.size() - 1);
  const float f = u - static_cast<float>(i);
  return colors[i] + f * (colors[j] - colors[i]);
}

void checkLogKnotCount(std::size_t count, const std::string& where) {
  if (count <= kMaxLogKnots) return;
  throw InputError(where + " holds " + std::to_string(count) + " knots; Kerf takes at most " +
                   std::to_string(kMaxLogKnots) +
                   " knots in a log (each needs 32 KiB of noise tables and is tested at every pixel it may "
                   "reach)");
}

void validate(const LogModel& log) {
  checkLogKnotCount(log.knots.size(), "log");
  const Stem& s = log.stem;
  if (!(s.heightStep > 0.0f) || !std::isfinite(s.heightStep))
    throw InputError("log: the slice spacing must be > 0");
  if (s.slices() < 2) throw InputError("log: the stem needs at least 2 slices");
  if (s.azimuths < 3) throw InputError("log: the stem needs at least 3 radius samples per slice");
  if (s.radii.size() != static_cast<std::size_t>(s.slices()) * s.azimuths) {
    throw InputError("log: the stem has " + std::to_string(s.radii.size()) + " radii, expected " +
                     std::to_string(s.slices()) + " slices x " + std::to_string(s.azimuths) + " azimuths");
  }
  for (const glm::vec2& p : s.pith) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("log: the pith has a non-finite point");
  }
  for (float r : s.radii) {
    if (!(r > 0.0f) || !std::isfinite(r))
      throw InputError("log: every stem radius must be a positive number");
  }
  checkPlausibleRadii(s.radii, s.azimuths, "log");
  for (std::size_t k = 0; k < log.knots.size(); ++k) {
    const Knot& knot = log.knots[k];
    const std::string name = "log: knot " + std::to_string(k);
    if (knot.samples() < 2 || knot.azimuths.size() != knot.heights.size()) {
      throw InputError(name + " needs at least 2 samples of height and azimuth (the same number of each)");
    }
    if (!(knot.distanceStep > 0.0f) || !std::isfinite(knot.distanceStep)) {
      throw InputError(name + ": the distance step must be > 0");
    }
    for (std::size_t j = 0; j < knot.heights.size(); ++j) {
      if (!std::isfinite(knot.heights[j]) || !std::isfinite(knot.azimuths[j])) {
        throw InputError(name + " has a non-finite height or azimuth");
      }
    }
    if (!(knot.deathDistance >= 0.0f)) throw InputError(name + ": the death distance must be >= 0");
    const float z0 = knot.heights[0];
    if (z0 < 0.0f || z0 > s.height()) {
      throw InputError(name + " starts at height " + std::to_string(z0) + " mm, outside the stem (0 to " +
                       std::to_string(s.height()) + " mm)");
    }
  }
}

void checkPlausibleRadii(const std::vector<float>& radii, int azimuths, const std::string& where) {
  if (radii.empty() || azimuths < 1) return;
  std::vector<float> sorted = radii;
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const float median = *middle;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const float r = radii[i];
    if (r <= median * kPlausibleRadiusFactor && r >= median / kPlausibleRadiusFactor) continue;
    std::ostringstream text;
    text << where << ": the stem radius " << r << " mm at slice " << i / static_cast<std::size_t>(azimuths)
         << ", azimuth " << i % static_cast<std::size_t>(azimuths)
         << " is not plausible: the log's median radius is " << median
         << " mm, and a stem's radius stays within " << kPlausibleRadiusFactor
         << "x of it (a measurement error?)";
    throw InputError(text.str());
  }
}

LogModel generateRandomLog(const RandomLogOptions& o) {
  if (!(o.lengthMm >= 20.0f) || !(o.radiusMm >= 10.0f) || !(o.whorlSpacingMm > 0.0f) || o.knotsPerWhorl < 0) {
    throw InputError(
        "random log: length >= 20 mm, radius >= 10 mm, whorl spacing > 0 and knots per whorl >= 0");
  }
  std::mt19937 rng(o.seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  LogModel log;
  log.name = "random log (seed " + std::to_string(o.seed) + ")";
  Stem& s = log.stem;
  s.heightStep = 10.0f;
  s.azimuths = 90;
  const int slices = static_cast<int>(std::ceil(o.lengthMm / s.heightStep)) + 1;
  // Pith: two slow bends (curvature), amplitude a few percent of the radius.
  const float bendA = 0.05f * o.radiusMm * (0.5f + unit(rng)), bendB = 0.03f * o.radiusMm * unit(rng);
  const float phaseA = kTwoPi * unit(rng), phaseB = kTwoPi * unit(rng), dirA = kTwoPi * unit(rng);
  const float waveA = 1.5f + 2.0f * unit(rng), waveB = 0.5f + unit(rng);
  s.pith.resize(slices);
  for (int i = 0; i < slices; ++i) {
    const float u = static_cast<float>(i) / static_cast<float>(slices - 1);
    const float a = bendA * std::sin(kTwoPi * u / waveA + phaseA),
                b = bendB * std::sin(kTwoPi * u * waveB + phaseB);
    s.pith[i] = glm::vec2(a * std::cos(dirA) - b * std::sin(dirA), a * std::sin(dirA) + b * std::cos(dirA));
  }
  const glm::vec2 middle = s.pith[slices / 2];
  for (glm::vec2& p : s.pith) p -= middle;
  // Outer radius: taper, ovality, a few lobes.
  const float ovality = 0.04f + 0.04f * unit(rng), ovalDir = kTwoPi * unit(rng);
  const float lobes = 0.02f * unit(rng), lobePhase = kTwoPi * unit(rng);
  s.radii.resize(static_cast<std::size_t>(slices) * s.azimuths);
  for (int i = 0; i < slices; ++i) {
    const float u = static_cast<float>(i) / static_cast<float>(slices - 1);
    for (int j = 0; j < s.azimuths; ++j) {
      const float th = kTwoPi * static_cast<float>(j) / static_cast<float>(s.azimuths);
      s.radii[static_cast<std::size_t>(i) * s.azimuths + j] =
          o.radiusMm * (1.08f - 0.16f * u) *
          (1.0f + ovality * std::cos(2.0f * (th - ovalDir)) +
           lobes * std::sin(5.0f * th + lobePhase + 3.0f * u));
    }
  }
  // Knots in whorls (spruce grows one whorl of branches per year at the top of the stem).
  const float maxD = 1.25f * o.radiusMm;
  const float step = 4.0f;
  const int samples = static_cast<int>(std::ceil(maxD / step)) + 1;
  auto addKnot = [&](float z0, float omega0, float size) {
    Knot k;
    k.distanceStep = step;
    const float rise = (0.15f + 0.35f * unit(rng)) * size;  // mm of rise per mm outward
    const float curl = (0.8f + 1.5f * unit(rng)) * size;    // early upward bend (sqrt term)
    const float twist = 0.04f * normal(rng);
    k.heights.resize(samples);
    k.azimuths.resize(samples);
    for (int j = 0; j < samples; ++j) {
      const float d = step * static_cast<float>(j);
      k.heights[j] = z0 + curl * std::sqrt(d) + rise * d;
      k.azimuths[j] = omega0 + twist * std::log1p(d);
    }
    // Alive to dead: branches low in the log died young (the crown rose above them).
    const float u = z0 / o.lengthMm;
    const float death = o.radiusMm * (0.25f + 0.6f * u + 0.25f * normal(rng));
    k.deathDistance = death > 0.95f * maxD ? std::numeric_limits<float>::infinity() : std::max(death, 6.0f);
    k.endDistance = std::numeric_limits<float>::infinity();
    log.knots.push_back(std::move(k));
  };
  for (float zw = 0.5f * o.whorlSpacingMm * (0.6f + 0.8f * unit(rng)); zw < o.lengthMm - 30.0f;
       zw += o.whorlSpacingMm * (0.75f + 0.5f * unit(rng))) {
    const float base = kTwoPi * unit(rng);
    for (int b = 0; b < o.knotsPerWhorl; ++b) {
      const float omega = base + kTwoPi * (static_cast<float>(b) + 0.35f * normal(rng)) / o.knotsPerWhorl;
      addKnot(zw + 8.0f * normal(rng), omega, 0.8f + 0.4f * unit(rng));
    }
    // An occasional small interwhorl branch.
    if (unit(rng) < 0.5f)
      addKnot(zw + o.whorlSpacingMm * (0.3f + 0.4f * unit(rng)), kTwoPi * unit(rng), 0.6f);
  }
  log.knots.erase(
      std::remove_if(log.knots.begin(), log.knots.end(),
                     [&](const Knot& k) { return k.heights[0] < 0.0f || k.heights[0] > s.height(); }),
      log.knots.end());
  validate(log);
  return log;
}

float knottiestHeight(const LogModel& log, float windowMm, float distanceMm) {
  if (log.knots.empty()) return 0.5f * log.stem.height();
  std::vector<float> starts;
  for (const Knot& k : log.knots) starts.push_back(k.heightAt(distanceMm));
  std::sort(starts.begin(), starts.end());
  std::size_t best = 0, bestFirst = 0, bestCount = 0, j = 0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    while (starts[j] < starts[i] - windowMm) ++j;
    if (i - j + 1 > bestCount) bestCount = i - j + 1, best = i, bestFirst = j;
  }
  // Midway between the lowest and the highest knot of the best window, kept inside the log.
  const float centre = 0.5f * (starts[bestFirst] + starts[best]);
  return std::clamp(centre, 0.5f * windowMm, std::max(0.5f * windowMm, log.stem.height() - 0.5f * windowMm));
}

}  // namespace kerf
