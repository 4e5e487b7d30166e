// The knot model of Larsson et al. 2022 (docs/knots.md) in GLSL: the twin of core/field/knot_field.cpp
// (KnotField::evaluate, KnotField::color) and of the log lookups of core/field/log_model.cpp. Same float
// operations in the same order; the per-knot noise is core's own table (KnotField::speedNoiseTable, built
// with the integer hashes of core/model/noise.hpp), uploaded as is and interpolated the same way, so
// no noise is recomputed here. Tables are read with texelFetch only (no filtering), so every sample is
// core's float.
//
// Only the knots that can reach the board are uploaded (KnotField::cull on the CPU, in ascending order);
// the fragment stage loops over the knots listed for its tile (board_knots.frag).

// Stem (Table 1).
uniform sampler2D u_pith;   // RG32F, slices x 1: pith x, y per slice
uniform sampler2D u_radii;  // R32F, azimuths x slices
uniform float u_heightStep;
uniform int u_slices;
uniform int u_azimuths;

// Knots (Table 2), board-culled, index k = 0..n-1.
uniform sampler2D u_knotTables;  // RG32F, samples x knots: z(d_j), omega(d_j)
uniform sampler2D u_knotInfo;    // RGBA32F, knots x 1: distance step, sample count, death distance, log index
uniform sampler2D u_knotNoise;   // RG32F: speed noise, outline noise; 64 x 64 per knot, 32 knots a row

// Colour map (Sec. 4.3), wrapped into rows of u_colorRowLength texels.
uniform sampler2D u_colors;  // RGB32F
uniform int u_colorCount;
uniform int u_colorRowLength;

// The knot parameters are the schema's uniforms (core/params/wood_parameters.def, group "knots",
// declared by glslUniformDeclarations() ahead of this file), set from the field's KnotSettings. The checks
// are the single-source kernel core/model/kernels/knot_checks.glsl (with kernels/noise.glsl), assembled ahead.

const float kKnotPi = 3.14159265358979;
const float kKnotTwoPi = 6.28318530717959;
const int kNoiseAngles = 64;
const int kNoiseTimes = 64;
const float kNoiseMaxTime = 1.5;
const int kNoiseKnotsPerRow = 32;

float knotSmoothstep01(float x) {
  x = clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

// log_model.cpp gridPosition.
void knotGridPosition(float x, float step, int count, out int i, out float f) {
  float u = clamp(x / step, 0.0, float(count - 1));
  i = min(int(u), max(count - 2, 0));
  f = u - float(i);
}

vec2 stemPithAt(float z) {
  int i;
  float f;
  knotGridPosition(z, u_heightStep, u_slices, i, f);
  vec2 a = texelFetch(u_pith, ivec2(i, 0), 0).xy;
  vec2 b = texelFetch(u_pith, ivec2(i + 1, 0), 0).xy;
  return a + f * (b - a);
}

float stemRadiusAt(float z, float azimuth) {
  int i;
  float f;
  knotGridPosition(z, u_heightStep, u_slices, i, f);
  int i1 = u_slices > 1 ? i + 1 : i;
  float n = float(u_azimuths);
  float a = azimuth * (n / kKnotTwoPi);
  a -= floor(a / n) * n;
  int j = int(a);
  float g = a - float(j);
  if (j >= u_azimuths) j = 0;
  int j1 = j + 1 == u_azimuths ? 0 : j + 1;
  float r00 = texelFetch(u_radii, ivec2(j, i), 0).r, r01 = texelFetch(u_radii, ivec2(j1, i), 0).r;
  float r10 = texelFetch(u_radii, ivec2(j, i1), 0).r, r11 = texelFetch(u_radii, ivec2(j1, i1), 0).r;
  float lower = r00 + g * (r01 - r00);
  float upper = r10 + g * (r11 - r10);
  return lower + f * (upper - lower);
}

// Knot::heightAt and Knot::azimuthAt together: (z(d), omega(d)).
vec2 knotSkeletonAt(int knot, vec4 info, float d) {
  int samples = int(info.y);
  if (samples == 1) return texelFetch(u_knotTables, ivec2(0, knot), 0).xy;
  int i;
  float f;
  knotGridPosition(d, info.x, samples, i, f);
  vec2 a = texelFetch(u_knotTables, ivec2(i, knot), 0).xy;
  vec2 b = texelFetch(u_knotTables, ivec2(i + 1, knot), 0).xy;
  return a + f * (b - a);
}

// KnotField::noiseAt for both tables at once: (speed noise, outline noise).
vec2 knotNoiseAt(int knot, float beta, float stemTime) {
  float u = beta * (float(kNoiseAngles) / kKnotTwoPi);
  u -= floor(u * (1.0 / float(kNoiseAngles))) * float(kNoiseAngles);
  int i = int(u);
  float fu = u - float(i);
  if (i >= kNoiseAngles) i = 0;
  int i1 = i + 1 == kNoiseAngles ? 0 : i + 1;
  float v = clamp(stemTime * (float(kNoiseTimes - 1) / kNoiseMaxTime), 0.0, float(kNoiseTimes - 1));
  int j = min(int(v), kNoiseTimes - 2);
  float fv = v - float(j);
  int row = (knot / kNoiseKnotsPerRow) * kNoiseTimes + j;
  int column = (knot % kNoiseKnotsPerRow) * kNoiseAngles;
  vec2 a = texelFetch(u_knotNoise, ivec2(column + i, row), 0).xy;
  vec2 b = texelFetch(u_knotNoise, ivec2(column + i1, row), 0).xy;
  vec2 c = texelFetch(u_knotNoise, ivec2(column + i, row + 1), 0).xy;
  vec2 e = texelFetch(u_knotNoise, ivec2(column + i1, row + 1), 0).xy;
  vec2 lower = a + fu * (b - a);
  vec2 upper = c + fu * (e - c);
  return lower + fv * (upper - lower);
}

// Eq. 2 (powerSmoothMin).
float knotPowerSmoothMin(float a, float b, float k) {
  float m = min(a, b), M = max(a, b);
  if (!(m > 0.0)) return max(m, 0.0);
  if (isinf(M)) return m;
  return m * pow(1.0 + pow(m / M, k), -1.0 / k);
}

// Sec. 4.2.1 (adaptiveK).
float knotAdaptiveK(float stemTime, float knotTime) {
  float delta = stemTime - knotTime;
  float sig = delta / (P.knotSmoothTransition + abs(delta));
  return 0.5 * (P.knotSmoothKnot + P.knotSmoothStem) + 0.5 * (P.knotSmoothKnot - P.knotSmoothStem) * sig;
}

// Sec. 4.2.2: knotDeadFactor, applyKnotDeath and the outline and shade of Sec. 4.3 are knot_death.glsl's,
// shared with the block's knots (assembled ahead of this file).

float knotWindow(float ratio) {
  if (ratio >= P.knotReachEnd) return 0.0;
  if (ratio <= P.knotReachStart) return 1.0;
  return 1.0 - knotSmoothstep01((ratio - P.knotReachStart) / (P.knotReachEnd - P.knotReachStart));
}

struct KnotSample {
  float time;
  float darkness;
  float deadShade;
  bool outline;
  float checks;
  int knotsInReach;
};

// The knots to evaluate: board-knot indices (ascending runs, one per tile), wrapped into rows.
uniform isampler2D u_tileKnots;  // R32I, u_tileListRow x rows
uniform int u_tileListRow;

// KnotField::evaluate over the knots u_tileKnots[first .. first + count).
KnotSample evaluateKnots(vec3 p, int first, int count) {
  KnotSample r;
  r.darkness = 0.0;
  r.deadShade = 0.0;
  r.outline = false;
  r.checks = 1.0;
  r.knotsInReach = 0;
  vec2 pith = stemPithAt(p.z);
  float qx = p.x - pith.x, qy = p.y - pith.y;
  float ds = sqrt(qx * qx + qy * qy);
  float theta = atan(qy, qx);
  float rs = stemRadiusAt(p.z, theta);
  float ts = ds / rs;
  r.time = ts;
  if (ds < 1e-3) return r;

  float reach = P.knotReachEnd * ds;
  float reach2 = reach * reach;
  float maxFraction = 0.9 * min(P.knotReachStart, P.knotReachEnd);
  float knotMin = 1e30, sumDelta = 0.0;
  for (int n = 0; n < count; ++n) {
    int at = first + n;
    int index = texelFetch(u_tileKnots, ivec2(at % u_tileListRow, at / u_tileListRow), 0).r;
    vec4 info = texelFetch(u_knotInfo, ivec2(index, 0), 0);
    vec2 skeleton = knotSkeletonAt(index, info, ds);
    float dz = p.z - skeleton.x;
    if (abs(dz) >= reach) continue;
    float dTheta = theta - skeleton.y;
    float along = ds * sin(dTheta);
    float radial = ds * (cos(dTheta) - 1.0);
    float db2 = along * along + radial * radial + dz * dz;
    if (db2 >= reach2) continue;
    float db = sqrt(db2);
    float ratio = db / ds;
    float window = knotWindow(ratio);
    float beta = atan(dz, along);
    vec2 noise = knotNoiseAt(index, beta, ts);
    float fraction = (P.knotSpeed - P.knotSpeedDecline * sqrt(ts)) * (1.0 + P.knotSpeedNoise * noise.x);
    fraction = clamp(fraction, 0.01, maxFraction);
    float tb = db / (fraction * rs);
    float k = knotAdaptiveK(ts, tb);
    float tDeath = info.z / rs;
    float tAlive = knotPowerSmoothMin(ts, tb, k);
    float delta = tAlive - min(ts, tb);
    if (ts > tDeath && ratio < P.knotReachStart) {
      float width = P.knotOutlineWidth * (1.0 + P.knotOutlineNoise * noise.y);
      if (inDeadKnotOutline(ts, tb, tDeath, width)) r.outline = true;
    }
    float section = fraction * rs * min(ts, tDeath);
    r.checks = min(r.checks, knotCheckShade(int(info.w), db, section, beta, ds, ts, tDeath, P.knotChecks));
    applyKnotDeath(ts, tAlive, tDeath, k, beta, tb, delta);  // Eq. 5
    r.deadShade = max(r.deadShade, deadKnotShade(ts, tb, tDeath));
    knotMin = min(knotMin, tb);
    sumDelta += window * delta;
    float inside = 1.0 - knotSmoothstep01((tb / ts - (1.0 - P.knotEdgeSoftness)) / max(P.knotEdgeSoftness, 1e-4));
    r.darkness = max(r.darkness, window * inside);
    ++r.knotsInReach;
  }
  if (r.knotsInReach > 0) {
    float depth = knotSmoothstep01(max(ts - knotMin, 0.0) / ts);
    r.time = max(min(ts, knotMin) + sumDelta * (1.0 - depth), 0.0);
  }
  return r;
}

// WoodColorMap::at.
vec3 knotColorMapAt(float t) {
  if (u_colorCount == 0) return vec3(0.5);
  float u = clamp(t, 0.0, 1.0) * float(u_colorCount - 1);
  int i = min(int(u), u_colorCount - 1);
  int j = min(i + 1, u_colorCount - 1);
  float f = u - float(i);
  vec3 a = texelFetch(u_colors, ivec2(i % u_colorRowLength, i / u_colorRowLength), 0).rgb;
  vec3 b = texelFetch(u_colors, ivec2(j % u_colorRowLength, j / u_colorRowLength), 0).rgb;
  return a + f * (b - a);
}

// KnotField::color.
vec3 knotColor(KnotSample s) {
  vec3 c = knotColorMapAt(s.time);
  c -= (s.darkness + s.deadShade) * P.knotDarkening;
  if (s.outline) c *= P.knotOutlineShade;
  c *= s.checks;
  return clamp(c, vec3(0.0), vec3(1.0));
}
