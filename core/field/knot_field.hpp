#pragma once
// The time field of a log with knots, Larsson et al. 2022 Sec. 4.1-4.3 (docs/knots.md):
// clang-format off
//   stem time    t_s = d_s / r_s(z, azimuth)              (Eq. 1, pseudo-nearest point at equal z)
//   knot time    T_b = d_b / v_b(beta, t_s)               (Eq. 1, pseudo-nearest point at equal d)
//   smooth min   smin(a, b, k) = (a^k b^k / (a^k + b^k))^(1/k)                         (Eq. 2)
//   smoothing    delta = smin - min (Eq. 3), smin' = min + delta'                      (Eq. 4)
//   adaptive k   k(t_s - T_b) between k_stem and k_knot                           (Sec. 4.2.1)
//   dead knots   delta' = f(tau, beta) * delta(t_s, T_b + tau, k + s tau)  (Eq. 5, Sec. 4.2.2)
//   many knots   t = min(t_s, T_b1..T_bn) + sum_i delta'_i                             (Eq. 6)
//   colour       1D colour map at t, knots darkened, noisy outline around dead knots (Sec. 4.3)
// clang-format on
//
// Every per-knot term is multiplied by a window that is exactly 0 once the distance d_b from the knot's
// pseudo-nearest skeleton point reaches knots.reach_end x d_s, and beyond it T_b > t_s, so a knot farther
// than that changes nothing, bit for bit. cull() uses that bound to list the knots that can reach a region.
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "field/log_model.hpp"
#include "params/parameter_schema.hpp"

namespace kerf {

// The knot parameters of the schema (group "knots", params/knot_parameters.def): one member per entry, with
// the schema's name and default, generated from those lines.
struct KnotSettings {
#define V1(a) float(a)
#define V3(a, b, c) glm::vec3(a, b, c)
#define KERF_PARAM(name, id, group, label, unit, kind, def, ...) KERF_PARAM_TYPE_##kind name = def;
#include "params/knot_parameters.def"
#undef KERF_PARAM
#undef V1
#undef V3

  static KnotSettings fromParameters(const WoodParameters& params);
  // Calls visit(spec, components) for every member, in schema order (spec: its ParamSpec; components:
  // 1 or 3 floats), e.g. to upload them as the shaders' P.knot* uniforms.
  template <typename Visit>
  void forEachParameter(Visit&& visit) const;
};

// Eq. 2, the power smooth minimum of two non-negative times; exact min(a, b) when either is 0.
float powerSmoothMin(float a, float b, float k);
// The same for any scalar type (float, or Ceres Jets in the block-knot fit,
// fit/block_knot_fit.hpp), and knotWindow below: the float functions call these (one implementation).
template <typename T>
T powerSmoothMinOf(const T& a, const T& b, const T& k) {
  using std::pow;
  // m (1 + (m/M)^k)^(-1/k), m = min, M = max: Eq. 2 without overflow for large k or 0/0 at t = 0.
  const T m = b < a ? b : a, M = a < b ? b : a;
  if (!(m > T(0))) return m > T(0) ? m : T(0);
  return m * pow(T(1) + pow(m / M, k), T(-1) / k);
}
template <typename T>
T knotWindowOf(const T& ratio, float reachStart, float reachEnd) {
  if (ratio >= T(reachEnd)) return T(0);
  if (ratio <= T(reachStart)) return T(1);
  T x = (ratio - T(reachStart)) / T(reachEnd - reachStart);
  x = x < T(0) ? T(0) : (T(1) < x ? T(1) : x);
  return T(1) - x * x * (T(3) - T(2) * x);
}
// Sec. 4.2.2, deadKnotFactor for any scalar type (the block-knot fit's Jets): the one implementation.
template <typename T>
T deadKnotFactorOf(const T& tau, const T& beta, const KnotSettings& s) {
  using std::cos;
  using std::exp;
  const T wing = T(1.0f) - T(s.knotButterfly) * cos(T(2.0f) * beta);  // 1 + b above/below, 1 - b at the sides
  const T progress = T(1.0f) - exp(-T(s.knotDeadTransition) * (tau > T(0.0f) ? tau : T(0.0f)));
  return T(1.0f) + (T(s.knotDeadInversion) * wing - T(1.0f)) * progress;
}
// Eq. 5 (Sec. 4.2.2), shared by the log (KnotField::evaluate) and the block's knots (BlockKnots::merge),
// all in stem time: where the alive union tAlive = smin(t_s, T_b, k) is later than the death time, the
// knot stops thickening (T_b += tau, tau = t_s - t_death: its section stays that of its death), the union
// sharpens (k + dead_sharpening tau) and the smoothing is scaled by f (inverted, butterfly). Returns
// whether the point lies past the death; then knotTime and delta are replaced.
template <typename T>
bool applyKnotDeath(const T& ts, const T& tAlive, const T& tDeath, const T& k, const T& beta,
                    const KnotSettings& s, T& knotTime, T& delta) {
  if (!(tAlive > tDeath)) return false;
  const T tau = ts - tDeath;
  knotTime += tau;
  const T m = knotTime < ts ? knotTime : ts;
  delta = deadKnotFactorOf(tau, beta, s) *
          (powerSmoothMinOf(ts, knotTime, T(k + T(s.knotDeadSharpening) * tau)) - m);
  return true;
}
// Sec. 4.3: inside the dark outline (bark ring) of a dead knot: on wood grown after the death, where the
// knot's surface froze (|T_b - t_death| < width, T_b the knot time before Eq. 5 moves it).
inline bool inDeadKnotOutline(float ts, float tb, float tDeath, float width) {
  return ts > tDeath && std::abs(tb - tDeath) < width;
}
// Sec. 4.3: the extra darkening of a dead knot's wood grown after its death (tb: the knot time after
// Eq. 5), growing over the first third of a stem-time unit.
inline float deadKnotShade(float ts, float tb, float tDeath, const KnotSettings& s) {
  if (!(ts > tDeath && tb < ts)) return 0.0f;
  return std::min(1.0f, 3.0f * (ts - tDeath)) * s.knotDeadDarkening;
}
// Eq. 3, the amount of smoothing smin - min (<= 0: the union pushes the rings outward).
float smoothingAmount(float a, float b, float k);
// Sec. 4.2.1: k_knot inside the knot (t_s > T_b), k_stem outside, blended smoothly over k_transition.
float adaptiveK(float stemTime, float knotTime, const KnotSettings& s);
// Sec. 4.2.2: the factor f on the smoothing of a dead knot, tau = stem time since death, beta = angle
// around the knot axis (0 = horizontal, pi/2 = above). f = 1 at death, tends to dead_inversion x the
// butterfly weight, which is 1 + butterfly above and below the knot and 1 - butterfly at its sides.
float deadKnotFactor(float tau, float beta, const KnotSettings& s);
// The window on a knot's terms as a function of d_b / d_s: 1 up to reach_start, 0 from reach_end on.
float knotWindow(float ratio, const KnotSettings& s);

struct KnotFieldSample {
  float time = 0;          // the merged time t (Eq. 6): 0 at the pith, 1 at the bark
  float stemTime = 0;      // t_s
  float knotTime = 1e30f;  // min over knots of the (dead-adjusted) knot time
  float darkness = 0;      // 0..1, how much of knots.darkening to subtract
  float deadShade = 0;     // extra darkening of dead knot wood (x knots.darkening)
  bool outline = false;    // inside the dark outline of a dead knot
  float checks = 1;        // colour factor of the knots' checks (knots.checks): 1 = no crack
  int knotsInReach = 0;    // knots whose window was non-zero here
};

// A colour map built from the schema's ring and colour parameters (rings of growth.ring_width over
// `radiusMm`, heartwood/sapwood colours), for logs that come without a photographed map (Sec. 4.3).
WoodColorMap woodColorMapFromParameters(const WoodParameters& params, float radiusMm);

class KnotField {
 public:
  KnotField(LogModel log, const KnotSettings& settings);

  const LogModel& log() const { return log_; }
  const KnotSettings& settings() const { return settings_; }

  // The field at a point of the log frame (mm), evaluating the listed knots (indices into log().knots,
  // ascending) or all of them.
  KnotFieldSample evaluate(const glm::vec3& p, std::span<const int> knots) const;
  KnotFieldSample evaluate(const glm::vec3& p) const { return evaluate(p, allKnots_); }
  glm::vec3 color(const KnotFieldSample& sample, const WoodColorMap& map) const;

  // Appends to `out` (ascending) those of `candidates` that may reach any point of the axis-aligned box
  // [lo, hi] (log frame): a conservative bound, so every other knot contributes exactly nothing there.
  void cull(const glm::vec3& lo, const glm::vec3& hi, std::span<const int> candidates,
            std::vector<int>& out) const;
  std::span<const int> allKnots() const { return allKnots_; }

  // The tabulated noise tables, for the GLSL twin (gpu/gpu_board_renderer.*): per knot
  // kNoiseTableTimes rows (stem time 0..kNoiseTableMaxTime) of kNoiseTableAngles angles (0..2 pi).
  static constexpr int kNoiseTableAngles = 64, kNoiseTableTimes = 64;
  static constexpr float kNoiseTableMaxTime = 1.5f;
  const std::vector<float>& speedNoiseTable() const { return speedNoise_; }
  const std::vector<float>& outlineNoiseTable() const { return outlineNoise_; }

 private:
  // Per knot, the periodic noise of Sec. 4.1 (knot speed) and 4.3 (outline width) tabulated over the angle
  // around the knot axis x the stem time, sampled bilinearly: the same noise at a fraction of the cost.
  float noiseAt(const std::vector<float>& table, int knot, float beta, float stemTime) const;

  LogModel log_;
  KnotSettings settings_;
  std::vector<int> allKnots_;
  std::vector<float> speedNoise_, outlineNoise_;
};

template <typename Visit>
void KnotSettings::forEachParameter(Visit&& visit) const {
#define KERF_PARAM(name, id, ...) visit(*findParameter(id), valueComponents(name));
#include "params/knot_parameters.def"
#undef KERF_PARAM
}

}  // namespace kerf
