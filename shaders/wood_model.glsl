// The GPU back-end of Kerf's wood model: the pith frame, the growth field read from a 3D texture and
// the block's knots from uniform arrays. The model itself (noise, ring profile, pores, rays, fibres,
// colour) is the single source core/model/kernels/*.glsl, which the C++ core compiles too (issue 15);
// core/model/kernels/wood.glsl lists what a back-end provides. tests/widgets/test_gpu_parity.cpp
// renders both back-ends and compares them (precision, sampling).
//
// Assembled by gpu/wood_program.cpp: "#version 330 core", kernels/glsl_prelude.glsl, the
// schema's struct WoodParameters and `uniform WoodParameters P` (kerf::glslUniformDeclarations()), 
// kernels/noise.glsl (with kPi), this file, kernels/wood.glsl.

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

struct Cylindrical {
  float height, radius, azimuth;
  vec3 radial, tangential;
  float x, y;
};

Cylindrical cylindricalOf(vec3 p, bool withAzimuth) {
  vec3 rel = p - u_axisOrigin;
  Cylindrical c;
  c.height = dot(rel, u_axisDirection);
  c.x = dot(rel, u_axisReference);
  c.y = dot(rel, u_axisBinormal);
  c.radius = sqrt(c.x * c.x + c.y * c.y);
  c.azimuth = withAzimuth ? atan(c.y, c.x) : 0.0;
  c.radial = c.radius > 1e-12 ? (c.x * u_axisReference + c.y * u_axisBinormal) / c.radius : u_axisReference;
  c.tangential = cross(u_axisDirection, c.radial);
  return c;
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

// --- Knots in the block (core/field/block_knots.*: Mokume Sec. 5.2.4 Eq. 7, Larsson et al. 2022) ----
// kMaxBlockKnots: prepended by WoodProgram (kMaxBlockKnotsOnGpu), which uploads at most this many.
uniform int u_blockKnotCount;
uniform vec3 u_blockKnotOrigin[kMaxBlockKnots];
uniform vec3 u_blockKnotDirection[kMaxBlockKnots];  // unit
uniform float u_blockKnotSpeed[kMaxBlockKnots];
uniform float u_blockKnotTaper[kMaxBlockKnots];     // BlockKnot::taper (0: the cone of Eq. 7)
uniform float u_blockKnotTaperAge[kMaxBlockKnots];  // years
uniform float u_blockKnotDeath[kMaxBlockKnots];     // BlockKnot::deathTime, years; a huge number: alive
uniform vec3 u_blockKnotUp[kMaxBlockKnots];         // BlockKnots::up/side: the frame of beta (knotAngleOf)
uniform vec3 u_blockKnotSide[kMaxBlockKnots];
uniform int u_blockKnotId[kMaxBlockKnots];          // BlockKnot::id: the seed of the knot's checks
// knotSmoothMinOf (Eq. 2) and the dead knot's Eq. 5 and Sec. 4.3: knot_death.glsl, assembled ahead.

// knotAngleOf: beta around the knot's axis, 0 beside it, pi/2 towards the pith axis' direction.
float blockKnotAngle(int i, vec3 p) {
  vec3 rel = p - u_blockKnotOrigin[i];
  vec3 u = u_blockKnotDirection[i];
  float along = rel.x * u.x + rel.y * u.y + rel.z * u.z;
  vec3 r = rel - along * u;
  vec3 up = u_blockKnotUp[i], side = u_blockKnotSide[i];
  return atan(r.x * up.x + r.y * up.y + r.z * up.z, r.x * side.x + r.y * side.y + r.z * side.z);
}

// Distance to the knot's half-line (knotAxisDistance).
float blockKnotDistance(int i, vec3 p) {
  vec3 rel = p - u_blockKnotOrigin[i];
  float along = max(dot(rel, u_blockKnotDirection[i]), 0.0);
  vec3 d = rel - along * u_blockKnotDirection[i];
  return sqrt(dot(d, d));
}

// knotSpeedAt: the knot's speed at stem time G, tapering (issue 19 item 2), capped below the reach; a dead
// knot's is the one of its death (the caller passes min(G, death)).
float blockKnotSpeed(int i, float stemTime) {
  float taper = u_blockKnotTaper[i];
  if (!(taper != 0.0)) return u_blockKnotSpeed[i];
  float v = u_blockKnotSpeed[i] * pow(max(stemTime, 1e-3) / u_blockKnotTaperAge[i], -taper);
  return min(v, 0.9 * min(P.knotReachStart, P.knotReachEnd));
}

// BlockKnots::merge (with knotTerm): G_k from the stem time; darkness and shade for Sec. 4.3.
float mergeBlockKnots(vec3 p, float stemTime, float stemRadius, out float darkness, out float shade) {
  darkness = 0.0;
  shade = 1.0;
  if (u_blockKnotCount == 0 || !(stemRadius > 1e-3)) return stemTime;
  float knotMin = stemTime, sumSmoothing = 0.0, deadShade = 0.0, checks = 1.0;
  int inReach = 0;
  for (int i = 0; i < u_blockKnotCount; ++i) {
    float distance = blockKnotDistance(i, p);
    float ratio = distance / stemRadius;
    if (ratio >= P.knotReachEnd) continue;  // out of reach: G unchanged
    float window = 1.0;
    if (!(ratio <= P.knotReachStart)) {
      float x = clamp((ratio - P.knotReachStart) / (P.knotReachEnd - P.knotReachStart), 0.0, 1.0);
      window = 1.0 - x * x * (3.0 - 2.0 * x);
    }
    float deathTime = u_blockKnotDeath[i];
    bool dead = deathTime < 1e30;
    float speed = blockKnotSpeed(i, min(stemTime, deathTime));
    float time = distance / (speed * P.ringWidth);
    float m = time < stemTime ? time : stemTime;
    float alive = knotSmoothMinOf(stemTime, time, P.knotSmoothStem);
    float delta = alive - m;
    float frozen = time;
    if (deathTime < stemTime) {
      // Eq. 5 in Larsson's stem time (stemTimePerYear), and back to years.
      float c = P.ringWidth / P.knotStemRadius;
      float knotTime = time * c;
      float deadDelta = delta * c;
      if (applyKnotDeath(stemTime * c, m * c, deathTime * c, P.knotSmoothStem, blockKnotAngle(i, p), knotTime,
                         deadDelta)) {
        time = knotTime / c;
        delta = deadDelta / c;
      }
    }
    knotMin = min(knotMin, time);
    sumSmoothing += window * delta;
    // Checks (knot_checks.glsl) in the knot's section (mm), frozen at its death.
    float section = speed * P.ringWidth * min(stemTime, deathTime);
    if (P.knotChecks > 0.0 && distance < section) {
      vec3 rel = p - u_blockKnotOrigin[i];
      vec3 u = u_blockKnotDirection[i];
      float along = rel.x * u.x + rel.y * u.y + rel.z * u.z;
      float c = P.ringWidth / P.knotStemRadius;
      checks = min(checks, knotCheckShade(u_blockKnotId[i], distance, section, blockKnotAngle(i, p), along,
                                          stemTime * c, deathTime * c, P.knotChecks));
    }
    if (dead) {
      float c = P.ringWidth / P.knotStemRadius;
      float ts = stemTime * c, tDeath = deathTime * c;
      if (distance < P.knotReachStart * stemRadius && inDeadKnotOutline(ts, frozen * c, tDeath, P.knotOutlineWidth))
        shade = P.knotOutlineShade;
      deadShade = max(deadShade, deadKnotShade(ts, time * c, tDeath));
    }
    if (stemTime > 0.0) {
      float e = clamp((time / stemTime - (1.0 - P.knotEdgeSoftness)) / max(P.knotEdgeSoftness, 1e-4), 0.0, 1.0);
      darkness = max(darkness, window * (1.0 - e * e * (3.0 - 2.0 * e)));
    }
    ++inReach;
  }
  darkness += deadShade;
  shade *= checks;
  return inReach > 0 ? max(knotMin + sumSmoothing, 0.0) : stemTime;
}

// The back-end functions core/model/kernels/wood.glsl calls.
float growthAt(Cylindrical c) { return growthField(c); }
float mergeKnots(vec3 p, float stemTime, float stemRadius, out float darkness, out float shade) {
  return mergeBlockKnots(p, stemTime, stemRadius, darkness, shade);
}
