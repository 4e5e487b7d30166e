// Kerf's wood model in GLSL: a line-by-line port of core/field/growth_field.cpp and
// core/material/wood_material.cpp (see those files for the paper sections). The CPU and this code must
// give the same picture; tests/widgets/test_gpu_parity.cpp renders both and compares them.
//
// Prepended at run time: "#version 330 core" and the schema's uniform declarations
// (kerf::glslUniformDeclarations(): one `u_<name>` per parameter of core/params/wood_parameters.def).

// --- Pith axis and growth-rate grid (set from kerf::GrowthField on the CPU) ------------------------
uniform vec3 u_axisOrigin;
uniform vec3 u_axisDirection;
uniform vec3 u_axisReference;
uniform vec3 u_axisBinormal;
uniform sampler3D u_growthTable;  // R32F, size (radii + 1, azimuths, heights): G at every radial node
uniform ivec3 u_gridSize;         // (heights, azimuths, radii)
uniform vec4 u_gridRange;         // (heightMin, heightMax, radiusMin, radiusMax) in mm
uniform vec2 u_azimuthRange;      // (azimuthMin, azimuthMax) radians: the full circle, or the block's part
uniform uint u_hashSeed;              // WoodMaterial's seed, derived from model.seed on the CPU

const float kPi = 3.14159265358979;

struct Cylindrical {
  float height, radius, azimuth;
  vec3 radial, tangential;
  float x, y;
};

Cylindrical toCylindrical(vec3 p) {
  vec3 rel = p - u_axisOrigin;
  Cylindrical c;
  c.height = dot(rel, u_axisDirection);
  c.x = dot(rel, u_axisReference);
  c.y = dot(rel, u_axisBinormal);
  c.radius = sqrt(c.x * c.x + c.y * c.y);
  c.azimuth = atan(c.y, c.x);
  c.radial = c.radius > 1e-12 ? (c.x * u_axisReference + c.y * u_axisBinormal) / c.radius : u_axisReference;
  c.tangential = cross(u_axisDirection, c.radial);
  return c;
}

// --- Hashing and noise (core/material/noise.hpp) ----------------------------------------------------
uint mixHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}
uint hash1(int a, uint seed) { return mixHash(uint(a) ^ mixHash(seed)); }
uint hash2(int a, int b, uint seed) { return mixHash(uint(b) ^ hash1(a, seed)); }
uint hash3(int a, int b, int c, uint seed) { return mixHash(uint(c) ^ hash2(a, b, seed)); }
float unitOf(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }
float signedUnitOf(uint h) { return unitOf(h) * 2.0 - 1.0; }

float fadeCurve(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
float fadeDerivative(float t) { return 30.0 * t * t * (t * (t - 2.0) + 1.0); }

float valueNoise1(float x, uint seed) {
  float fl = floor(x);
  int i = int(fl);
  float t = fadeCurve(x - fl);
  float a = signedUnitOf(hash1(i, seed)), b = signedUnitOf(hash1(i + 1, seed));
  return a + t * (b - a);
}

vec4 valueNoise3(vec3 p, uint seed) {
  vec3 fl = floor(p);
  int ix = int(fl.x), iy = int(fl.y), iz = int(fl.z);
  vec3 f = p - fl;
  vec3 u = vec3(fadeCurve(f.x), fadeCurve(f.y), fadeCurve(f.z));
  vec3 du = vec3(fadeDerivative(f.x), fadeDerivative(f.y), fadeDerivative(f.z));
  float a = signedUnitOf(hash3(ix, iy, iz, seed)), b = signedUnitOf(hash3(ix + 1, iy, iz, seed));
  float c = signedUnitOf(hash3(ix, iy + 1, iz, seed)), d = signedUnitOf(hash3(ix + 1, iy + 1, iz, seed));
  float e = signedUnitOf(hash3(ix, iy, iz + 1, seed)), g = signedUnitOf(hash3(ix + 1, iy, iz + 1, seed));
  float h = signedUnitOf(hash3(ix, iy + 1, iz + 1, seed)), k = signedUnitOf(hash3(ix + 1, iy + 1, iz + 1, seed));
  float k1 = b - a, k2 = c - a, k3 = e - a, k4 = a - b - c + d, k5 = a - c - e + h, k6 = a - b - e + g,
        k7 = -a + b + c - d + e - g - h + k;
  float v = a + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z + k6 * u.z * u.x +
            k7 * u.x * u.y * u.z;
  vec3 grad = vec3(du.x * (k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z),
                   du.y * (k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x),
                   du.z * (k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y));
  return vec4(v, grad);
}

vec4 fractalNoise3(vec3 p, uint seed) {
  vec4 a = valueNoise3(p, seed);
  vec4 b = valueNoise3(p * 2.03 + vec3(17.1, 3.7, 9.3), seed + 101u);
  return a + vec4(0.5 * b.x, 1.015 * b.yzw);
}

// --- Growth field (core/field/growth_field.cpp) -------------------------------------------------------
float growthNode(int ih, int ia, int ir) { return texelFetch(u_growthTable, ivec3(ir, ia, ih), 0).r; }

float growthRadial(int ih, int ia, float r) {
  int nr = u_gridSize.z;
  float radiusMin = u_gridRange.z, radiusMax = u_gridRange.w;
  if (r <= radiusMin) return radiusMin > 0.0 ? growthNode(ih, ia, 0) * (r / radiusMin) : 0.0;
  float step = (radiusMax - radiusMin) / float(nr);
  float f = (r - radiusMin) / step;
  if (f >= float(nr)) {
    // Beyond the last node: continue with the last cell's rate (its node difference over one step).
    float lastRate = (growthNode(ih, ia, nr) - growthNode(ih, ia, nr - 1)) / step;
    return growthNode(ih, ia, nr) + (r - radiusMax) * lastRate;
  }
  int ir = int(f);
  float t = f - float(ir);
  float a = growthNode(ih, ia, ir);
  return a + t * (growthNode(ih, ia, ir + 1) - a);
}

void bsplineWeights(float t, out vec4 w) {
  float s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  w = vec4(s * s * s, 3.0 * t3 - 6.0 * t2 + 4.0, -3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0, t3) / 6.0;
}

// core/field/growth_rates.cpp gridStencil(): heights and spokes blended with B-spline weights.
float wrapTwoPi(float x) { return x - 2.0 * kPi * floor(x / (2.0 * kPi)); }

float growthField(Cylindrical c) {
  int nh = u_gridSize.x, na = u_gridSize.y;
  float fh = 0.0;
  if (nh > 1) fh = clamp((c.height - u_gridRange.x) / (u_gridRange.y - u_gridRange.x) * float(nh - 1), 0.0, float(nh - 1));
  int ih = min(int(fh), nh - 1);
  vec4 wh, wa;
  bsplineWeights(fh - float(ih), wh);
  ivec4 spokes;
  if (u_azimuthRange.y - u_azimuthRange.x >= 2.0 * kPi - 1e-4) {
    float fa = clamp(wrapTwoPi(c.azimuth - u_azimuthRange.x) * (float(na) / (2.0 * kPi)), 0.0, float(na));
    int ia = int(fa);
    bsplineWeights(fa - float(ia), wa);
    for (int j = 0; j < 4; ++j) spokes[j] = (ia - 1 + j + na) % na;
  } else {
    float mid = 0.5 * (u_azimuthRange.x + u_azimuthRange.y), halfRange = 0.5 * (u_azimuthRange.y - u_azimuthRange.x);
    float rel = wrapTwoPi(c.azimuth - mid + kPi) - kPi;
    float fa = na > 1 ? clamp((rel + halfRange) / (2.0 * halfRange) * float(na - 1), 0.0, float(na - 1)) : 0.0;
    int ia = min(int(fa), na - 1);
    bsplineWeights(fa - float(ia), wa);
    for (int j = 0; j < 4; ++j) spokes[j] = clamp(ia - 1 + j, 0, na - 1);
  }
  float g = 0.0;
  for (int i = 0; i < 4; ++i) {
    int h = clamp(ih - 1 + i, 0, nh - 1);
    float row = 0.0;
    for (int j = 0; j < 4; ++j) row += wa[j] * growthRadial(h, spokes[j], c.radius);
    g += wh[i] * row;
  }
  return g;
}

// --- Texture (core/material/wood_material.cpp) --------------------------------------------------------
const uint kDistortRadial = 1u, kDistortTangential = 2u, kRingColor = 3u, kMottle = 4u, kFiber = 5u,
           kPoreColumn = 6u, kPoreCell = 7u, kRayColumn = 8u, kRayCell = 9u;

float stepSmooth(float a, float b, float x) {
  if (b <= a) return x < a ? 0.0 : 1.0;
  float t = clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

float wyvill(float d2) {
  float w = 1.0 - d2;
  return w > 0.0 ? w * w * w : 0.0;
}

vec3 undistort(vec3 p, Cylindrical c, out vec3 fiberDirection) {
  float amplitude = u_distortionAmplitude;
  fiberDirection = u_axisDirection;
  if (amplitude <= 0.0) return p;
  float s = u_distortionScale, along = u_distortionScale * u_distortionStretch;
  vec3 q = vec3(c.x / s, c.y / s, c.height / along);
  vec4 nr = fractalNoise3(q, u_hashSeed + kDistortRadial);
  vec4 nt = fractalNoise3(q + vec3(31.4, 27.1, 8.2), u_hashSeed + kDistortTangential);
  vec3 gr = amplitude * (nr.y / s * u_axisReference + nr.z / s * u_axisBinormal + nr.w / along * u_axisDirection);
  vec3 gt = amplitude * (nt.y / s * u_axisReference + nt.z / s * u_axisBinormal + nt.w / along * u_axisDirection);
  float compress = 1.0 / sqrt(1.0 + dot(gr, gr) + dot(gt, gt));
  mat3 jacobian = mat3(1.0) + compress * (outerProduct(c.radial, gr) + outerProduct(c.tangential, gt));
  fiberDirection = normalize(inverse(jacobian) * u_axisDirection);
  return p + amplitude * nr.x * c.radial + amplitude * nt.x * c.tangential;
}

float seasonOf(float year) {
  float f = year - u_ringOffset - floor(year - u_ringOffset);
  float latewoodStart = 1.0 - u_latewoodFraction;
  float rise = stepSmooth(latewoodStart * (1.0 - u_transition), latewoodStart + 1e-4, f);
  float fall = 1.0 - stepSmooth(1.0 - u_boundarySoftness, 1.0, f);
  return rise * fall;
}

float poreWeight(Cylindrical c, float season) {
  float radius = u_poreRadiusEarly + season * (u_poreRadiusLate - u_poreRadiusEarly);
  float density = u_poreDensityEarly + season * (u_poreDensityLate - u_poreDensityEarly);
  if (radius <= 0.0 || density <= 0.0) return 0.0;
  float cell = u_poreCellSize, len = u_poreLength;
  float r = min(radius, 0.45 * cell);
  int i = int(floor(c.x / cell));
  int j = int(floor(c.y / cell));
  float stagger = unitOf(hash2(i, j, u_hashSeed + kPoreColumn)) * len;
  int k = int(floor((c.height + stagger) / len));
  uint h = hash3(i, j, k, u_hashSeed + kPoreCell);
  if (unitOf(h) >= density) return 0.0;
  float room = 0.5 - r / cell;
  float cx = (float(i) + 0.5 + room * signedUnitOf(mixHash(h ^ 0x9e3779b9u))) * cell;
  float cy = (float(j) + 0.5 + room * signedUnitOf(mixHash(h ^ 0x85ebca6bu))) * cell;
  float halfLength = 0.5 * len * (0.6 + 0.35 * unitOf(mixHash(h ^ 0xc2b2ae35u)));
  float ch = (float(k) + 0.5) * len - stagger;
  float dx = c.x - cx, dy = c.y - cy, dh = (c.height - ch) / halfLength;
  return wyvill((dx * dx + dy * dy) / (r * r) + dh * dh);
}

float rayWeight(Cylindrical c) {
  if (u_rayDensity <= 0.0 || u_rayOpacity <= 0.0) return 0.0;
  float bandLength = u_rayLength;
  int band = int(floor(c.radius / bandLength));
  float bandMiddle = (float(band) + 0.5) * bandLength;
  int count = max(1, int(round(2.0 * kPi * bandMiddle / u_raySpacing)));
  float sector = 2.0 * kPi / float(count);
  int i = min(int((c.azimuth + kPi) / sector), count - 1);
  float cellHeight = 3.0 * u_rayHeight;
  float stagger = unitOf(hash2(band, i, u_hashSeed + kRayColumn)) * cellHeight;
  int k = int(floor((c.height + stagger) / cellHeight));
  uint h = hash3(band, i, k, u_hashSeed + kRayCell);
  if (unitOf(h) >= u_rayDensity) return 0.0;
  float centerAngle = -kPi + (float(i) + 0.5 + 0.3 * signedUnitOf(mixHash(h ^ 0x9e3779b9u))) * sector;
  float dAngle = c.azimuth - centerAngle;
  dAngle -= 2.0 * kPi * round(dAngle / (2.0 * kPi));
  float centerHeight = (float(k) + 0.5 + 0.15 * signedUnitOf(mixHash(h ^ 0x85ebca6bu))) * cellHeight - stagger;
  float dt = c.radius * dAngle / u_rayWidth;
  float dh = (c.height - centerHeight) / u_rayHeight;
  float q = c.radius / bandLength - float(band);
  float taper = stepSmooth(0.0, 0.12, q) * (1.0 - stepSmooth(0.88, 1.0, q));
  return wyvill(dt * dt + dh * dh) * taper;
}

// --- Knots in the block (core/field/block_knots.*: Mokume Sec. 5.2.4 Eq. 7, Larsson et al. 2022) ----
const int kMaxBlockKnots = 8;  // WoodProgram uploads at most this many
uniform int u_blockKnotCount;
uniform vec3 u_blockKnotOrigin[kMaxBlockKnots];
uniform vec3 u_blockKnotDirection[kMaxBlockKnots];  // unit
uniform float u_blockKnotSpeed[kMaxBlockKnots];

// Eq. 2 (powerSmoothMinOf).
float blockKnotSmoothMin(float a, float b, float k) {
  float m = b < a ? b : a, M = a < b ? b : a;
  if (!(m > 0.0)) return max(m, 0.0);
  return m * pow(1.0 + pow(m / M, k), -1.0 / k);
}

// Distance to the knot's half-line (knotAxisDistance).
float blockKnotDistance(int i, vec3 p) {
  vec3 rel = p - u_blockKnotOrigin[i];
  float along = max(dot(rel, u_blockKnotDirection[i]), 0.0);
  vec3 d = rel - along * u_blockKnotDirection[i];
  return sqrt(dot(d, d));
}

// BlockKnots::merge: G_k from the stem time; darkness for Sec. 4.3.
float mergeBlockKnots(vec3 p, float stemTime, float stemRadius, out float darkness) {
  darkness = 0.0;
  if (u_blockKnotCount == 0 || !(stemRadius > 1e-3)) return stemTime;
  float knotMin = stemTime, sumSmoothing = 0.0;
  int inReach = 0;
  for (int i = 0; i < u_blockKnotCount; ++i) {
    float distance = blockKnotDistance(i, p);
    float ratio = distance / stemRadius;
    if (ratio >= u_knotReachEnd) continue;  // out of reach: G unchanged
    float window = 1.0;
    if (!(ratio <= u_knotReachStart)) {
      float x = clamp((ratio - u_knotReachStart) / (u_knotReachEnd - u_knotReachStart), 0.0, 1.0);
      window = 1.0 - x * x * (3.0 - 2.0 * x);
    }
    float time = distance / (u_blockKnotSpeed[i] * u_ringWidth);
    knotMin = min(knotMin, time);
    sumSmoothing += window * (blockKnotSmoothMin(stemTime, time, u_knotSmoothStem) - min(time, stemTime));
    if (stemTime > 0.0) {
      float e = clamp((time / stemTime - (1.0 - u_knotEdgeSoftness)) / max(u_knotEdgeSoftness, 1e-4), 0.0, 1.0);
      darkness = max(darkness, window * (1.0 - e * e * (3.0 - 2.0 * e)));
    }
    ++inReach;
  }
  return inReach > 0 ? max(knotMin + sumSmoothing, 0.0) : stemTime;
}

struct WoodSample {
  float year, latewood, pore, ray;
  vec3 color, fiberDirection;
};

// faceIndex 0..5 applies that face's tint, -1 none (as WoodMaterial::evaluate).
WoodSample evaluateWood(vec3 p, int faceIndex) {
  WoodSample s;
  Cylindrical distorted = toCylindrical(p);
  vec3 u = undistort(p, distorted, s.fiberDirection);
  Cylindrical c = toCylindrical(u);
  s.year = growthField(c);
  float knotDarkness;
  s.year = mergeBlockKnots(u, s.year, c.radius, knotDarkness);  // Mokume Sec. 5.2.4 Eq. 7
  s.latewood = seasonOf(s.year);
  s.pore = poreWeight(c, s.latewood);
  s.ray = rayWeight(c);

  float t = s.latewood;
  t += 0.5 * u_ringColorVariation * valueNoise1(s.year, u_hashSeed + kRingColor);
  if (u_mottleStrength > 0.0) {
    float m = u_mottleScale;
    t += 0.5 * u_mottleStrength * fractalNoise3(vec3(c.x / m, c.y / m, c.height / (4.0 * m)), u_hashSeed + kMottle).x;
  }
  if (u_fiberStrength > 0.0) {
    vec3 q = vec3(c.x / u_fiberWidth, c.y / u_fiberWidth, c.height / u_fiberLength);
    t += 0.5 * u_fiberStrength * valueNoise3(q, u_hashSeed + kFiber).x;
  }
  t += u_poreDarkness * s.pore;

  float sap = stepSmooth(u_sapwoodStart - 0.5 * u_sapwoodTransition, u_sapwoodStart + 0.5 * u_sapwoodTransition, s.year);
  vec3 early = max(mix(u_earlywoodColor, u_sapwoodEarlywoodColor, sap), vec3(1e-3));
  vec3 late = max(mix(u_latewoodColor, u_sapwoodLatewoodColor, sap), vec3(1e-3));
  vec3 color = early * pow(late / early, vec3(t));
  color = mix(color, u_rayColor, u_rayOpacity * s.ray);
  color -= knotDarkness * u_knotDarkening;  // Larsson et al. 2022 Sec. 4.3
  if (faceIndex == 0) color *= u_faceTintA;
  else if (faceIndex == 1) color *= u_faceTintB;
  else if (faceIndex == 2) color *= u_faceTintC;
  else if (faceIndex == 3) color *= u_faceTintD;
  else if (faceIndex == 4) color *= u_faceTintE;
  else if (faceIndex == 5) color *= u_faceTintF;
  s.color = clamp(color, 0.0, 1.0);
  return s;
}
