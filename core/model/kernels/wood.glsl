// The procedural wood texture, single source for the core (material/wood_kernels.hpp) and the shaders
// (gpu/wood_program.cpp): the forward model of Liu et al. 2016 (Sec. 4) as simplified and
// extended by Mokume Sec. 5.3.1 / A.2.3, evaluated on top of the growth field.
//
// Colour follows Beer's law (Liu 4.3): every colour is earlywood * (latewood/earlywood)^t, t being the
// pigment concentration: 0 in earlywood, 1 in latewood, plus 1D ring noise and 3D mottling (Liu 4.4),
// fibre streaks, and pores (Liu 4.6) which raise t. Heartwood and sapwood each have an
// earlywood/latewood pair (Mokume's radial colour maps, A.2.3). Rays (Liu 4.6) blend towards their own
// colour. A per-face tint models differences between photographed faces (Mokume A.2.3).
//
// What each back-end provides (uniforms in GLSL, members in C++):
//   P                  the schema's parameters (struct WoodParameters, core/params/wood_parameters.def)
//   u_hashSeed         the seed derived from model.seed
//   u_axisDirection, u_axisReference, u_axisBinormal   the pith frame (field/pith_axis.hpp)
//   Cylindrical cylindricalOf(vec3 p, bool withAzimuth)  the pith axis' coordinates of a point
//   float growthAt(Cylindrical c)                         the growth field G (years)
//   float mergeKnots(vec3 p, float stemTime, float stemRadius, KERF_OUT(float) darkness, KERF_OUT(float) shade)
//                                 knots merged into G (Mokume Sec. 5.2.4 Eq. 7); darkness x knots.darkening is
//                                 subtracted, shade multiplies (a dead knot's bark ring, Larsson 2022 Sec. 4.3)

// Independent sub-seeds for the model's random features, all derived from model.seed.
KERF_CONST uint kDistortRadial = 1u;
KERF_CONST uint kDistortTangential = 2u;
KERF_CONST uint kRingColor = 3u;
KERF_CONST uint kMottle = 4u;
KERF_CONST uint kFiber = 5u;
KERF_CONST uint kPoreColumn = 6u;
KERF_CONST uint kPoreCell = 7u;
KERF_CONST uint kRayColumn = 8u;
KERF_CONST uint kRayCell = 9u;
KERF_CONST uint kFiberStagger = 10u;

// Pores are open vessels: a hole's shadow darkens the wood by a fixed factor per unit of pores.darkness,
// whatever the wood's pigment. (As extra pigment t they vanished wherever the fitted latewood colour came
// close to the earlywood's, as on CN03 - issue 16. Following the pigment's hue instead let the colour fit
// turn CN03's pores olive.) 0.5 keeps the default species' pores about as dark as before.
KERF_CONST float kPoreShadow = 0.5f;
// Fibre streaks (Mokume A.2.3) are a shade of the same kind, lighter and darker by turns: as pigment t
// they scaled with log(latewood / earlywood) and vanished on CN03, whose fitted colours lie within 15 % of
// each other, while its photos show the fibres on every long-grain face. exp(+-0.25) at strength 1.
KERF_CONST float kFiberShade = 0.25f;

struct WoodSample {
  float year;           // growth field value G (years since the pith) at the distorted point
  float latewood;       // season blend s in [0, 1]: 0 earlywood, 1 latewood
  float pigment;        // Beer's-law concentration t: colour = early * (late / early)^t
  float pore;           // pore weight in [0, 1] (Wyvill kernel)
  vec3 shade;           // factor on the colour: the pore's shadow times the fibre streaks
  float ray;            // ray weight in [0, 1]
  vec3 color;           // RGB in [0, 1], as stored in 8-bit images (sRGB-encoded)
  vec3 fiberDirection;  // unit, block frame (the pith direction unless asked for)
};

float stepSmooth(float a, float b, float x) {
  if (b <= a) return x < a ? 0.0f : 1.0f;
  float t = clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Wyvill kernel (Liu Sec. 4.6) of a squared distance already divided by the squared influence radius.
// A vessel seen in a cut is a hole: dark across most of its radius with a soft rim. (The Wyvill blob's dark
// core was half the radius, so CN03's pores read as faint specks - issue 16.)
float holeProfile(float d2) {
  return 1.0f - stepSmooth(0.45f, 1.0f, d2);
}

// The colour factor of a pore's shadow: exp(-kPoreShadow * darkness * pore) in luminance, absorbed per
// channel as pores.shadow_hue says (its mean normalised away, so pores.darkness alone sets how dark).
vec3 shadeOf(float amount) {
  vec3 hue = max(P.poreShadowHue, vec3(1e-3f));
  return exp(-(amount / ((hue.x + hue.y + hue.z) / 3.0f)) * hue);
}
vec3 poreShadeOf(float pore) { return shadeOf(kPoreShadow * P.poreDarkness * pore); }

// A fibre streak's shade at the undistorted point: value noise stretched along the fibres (the height),
// in [-1, 1], so the streaks leave the mean colour as it was. The noise's lattice planes across the
// fibres are staggered by a smooth offset, else every streak would end at the same heights and long grain
// would show rows across it every fibres.length.
// In two steps: the noise (fibers.width and fibers.length) and its shade (fibers.strength).
float fiberNoiseAt(Cylindrical c) {
  vec3 q = vec3(c.x / P.fiberWidth, c.y / P.fiberWidth, c.height / P.fiberLength);
  q.z += 2.0f * valueNoise3(vec3(0.5f * q.x, 0.5f * q.y, 0.0f), u_hashSeed + kFiberStagger).x;
  return valueNoise3(q, u_hashSeed + kFiber).x;
}
vec3 fiberShadeOf(float noise) {
  if (P.fiberStrength <= 0.0f) return vec3(1.0f);
  return shadeOf(kFiberShade * P.fiberStrength * noise);
}

float wyvill(float d2) {
  float w = 1.0f - d2;
  return w > 0.0f ? w * w * w : 0.0f;
}

// Liu Eq. 1: the distortion f(p) = p + m_r r + m_theta theta, returning the undistorted point, and (when
// asked) the distorted fibre direction J^-1 V with J compressed as in Liu Eq. 3.
vec3 undistort(vec3 p, Cylindrical c, bool wantFiber, KERF_OUT(vec3) fiberDirection) {
  float amplitude = P.distortionAmplitude;
  fiberDirection = u_axisDirection;
  if (amplitude <= 0.0f) return p;
  float s = P.distortionScale;
  float along = P.distortionScale * P.distortionStretch;
  vec3 q = vec3(c.x / s, c.y / s, c.height / along);
  vec4 nr = fractalNoise3(q, u_hashSeed + kDistortRadial);
  vec4 nt = fractalNoise3(q + vec3(31.4f, 27.1f, 8.2f), u_hashSeed + kDistortTangential);
  if (wantFiber) {
    // Gradients of m_r, m_theta with respect to p (chain rule through the tree frame).
    vec3 gr = amplitude * (nr.y / s * u_axisReference + nr.z / s * u_axisBinormal + nr.w / along * u_axisDirection);
    vec3 gt = amplitude * (nt.y / s * u_axisReference + nt.z / s * u_axisBinormal + nt.w / along * u_axisDirection);
    float compress = 1.0f / sqrt(1.0f + dot(gr, gr) + dot(gt, gt));  // Liu Eq. 3
    mat3 jacobian = mat3(1.0f) + compress * (outerProduct(c.radial, gr) + outerProduct(c.tangential, gt));
    fiberDirection = normalize(inverse(jacobian) * u_axisDirection);
  }
  return p + amplitude * nr.x * c.radial + amplitude * nt.x * c.tangential;
}

// Where in its year a growth time lies: 0 at a ring boundary, rising to 1 at the next.
float yearPhase(float year) {
  return year - P.ringOffset - floor(year - P.ringOffset);
}

// Liu Sec. 4.2: a square wave over the year with a controllable early-to-latewood transition, the
// earlywood taking `earlywoodShare` of the year.
float seasonWith(float year, float earlywoodShare) {
  float f = yearPhase(year);
  float latewoodStart = earlywoodShare;
  float rise = stepSmooth(latewoodStart * (1.0f - P.transition), latewoodStart + 1e-4f, f);
  float fall = 1.0f - stepSmooth(1.0f - P.boundarySoftness, 1.0f, f);
  return rise * fall;
}
float seasonOf(float year) {
  return seasonWith(year, 1.0f - P.latewoodFraction);
}
// The same for the vessels: their earlywood zone is pores.earlywood_zone times the colour's.
float poreEarlywoodShare() {
  return clamp((1.0f - P.latewoodFraction) * P.poreZone, 0.0f, 1.0f);
}

// The fitted ring profile (Mokume Sec. 5.3.2's base colour as a function of the growth value): extra
// pigment at eight points of the year, interpolated periodically (Catmull-Rom), so the fit can give the
// ring the shading the photos show - e.g. oak's dark band of earlywood pores - beyond the square wave.
float ringProfileKnot(int k) {
  int i = k - 8 * int(floor(float(k) / 8.0f));
  if (i == 0) return P.ringProfile0;
  if (i == 1) return P.ringProfile1;
  if (i == 2) return P.ringProfile2;
  if (i == 3) return P.ringProfile3;
  if (i == 4) return P.ringProfile4;
  if (i == 5) return P.ringProfile5;
  if (i == 6) return P.ringProfile6;
  return P.ringProfile7;
}

// Uniform Catmull-Rom weights of the knots k-1, k, k+1, k+2 at t in [0, 1) between knots k and k+1.
vec4 catmullRomWeights(float t) {
  return 0.5f * vec4(t * ((2.0f - t) * t - 1.0f), t * t * (3.0f * t - 5.0f) + 2.0f,
                     t * ((4.0f - 3.0f * t) * t + 1.0f), t * t * (t - 1.0f));
}

// The knot k before the point of the year at `year`, and the weights of knots k-1 .. k+2 there.
int ringProfileCell(float year, KERF_OUT(vec4) weights) {
  float x = 8.0f * yearPhase(year);
  int k = min(int(floor(x)), 7);
  weights = catmullRomWeights(x - float(k));
  return k;
}

float ringProfileAt(float year) {
  vec4 w;
  int k = ringProfileCell(year, w);
  return w.x * ringProfileKnot(k - 1) + w.y * ringProfileKnot(k) + w.z * ringProfileKnot(k + 1) +
         w.w * ringProfileKnot(k + 2);
}

// Liu Sec. 4.6 / Mokume A.2.3: vessels are tubes along the fibres - dots on end grain, streaks of a few
// mm on long grain. Placement without a lattice (issue 16): each cross-section cell holds up to
// kPoresPerCell vessel columns anywhere inside it (so neighbours can crowd or leave gaps, as in real
// wood), each column is split into vessel segments of random length and stagger along the grain, and
// every segment has its own radius. A pore can reach into the neighbouring cells, so the 3 x 3 cells
// around the point are searched; the radius is capped at one cell for that.
KERF_CONST int kPoresPerCell = 2;

float poreWeight(Cylindrical c, float year) {
  float earlywoodShare = poreEarlywoodShare();
  float season = seasonWith(year, earlywoodShare);
  float radius = P.poreRadiusEarly + season * (P.poreRadiusLate - P.poreRadiusEarly);
  if (P.poreEarlyTaper > 0.0f) {
    // pores.earlywood_taper: 1 + taper (1/2 - where in the earlywood), on the earlywood's share of the
    // radius; the mean over the earlywood stays pores.radius_earlywood.
    float intoEarlywood = clamp(yearPhase(year) / max(earlywoodShare, 0.01f), 0.0f, 1.0f);
    radius *= 1.0f + (1.0f - season) * P.poreEarlyTaper * (0.5f - intoEarlywood);
  }
  float densityEarly = P.poreDensityEarly;
  if (P.poreEarlyThinning > 0.0f) {
    // pores.earlywood_thinning: the earlywood's density falls linearly across the pore zone. Past the zone
    // nothing is thinned: the soft ring boundary at the year's end is the next year's first row.
    float phase = yearPhase(year);
    float intoZone = phase < earlywoodShare ? phase / max(earlywoodShare, 0.01f) : 0.0f;
    densityEarly *= 1.0f - P.poreEarlyThinning * intoZone;
  }
  float density = densityEarly + season * (P.poreDensityLate - densityEarly);
  if (radius <= 0.0f || density <= 0.0f) return 0.0f;
  float cell = P.poreCellSize;
  int ci = int(floor(c.x / cell));
  int cj = int(floor(c.y / cell));
  // A pore's centre lies in its cell and it reaches no farther than r <= min(1.3 radius, cell) (below):
  // a neighbouring cell farther away than that on either side cannot touch this point. Small pores need
  // 4 cells of the 9 (the same weight, 2x faster; 1 % margin for rounding).
  float reach = 1.01f * min(1.3f * radius, cell);
  float fx = (c.x / cell - float(ci)) * cell;
  float fy = (c.y / cell - float(cj)) * cell;
  int iFrom = fx < reach ? -1 : 0;
  int iTo = cell - fx < reach ? 1 : 0;
  int jFrom = fy < reach ? -1 : 0;
  int jTo = cell - fy < reach ? 1 : 0;
  float weight = 0.0f;
  for (int di = iFrom; di <= iTo; ++di) {
    for (int dj = jFrom; dj <= jTo; ++dj) {
      int i = ci + di;
      int j = cj + dj;
      uint column = hash2(i, j, u_hashSeed + kPoreColumn);
      for (int n = 0; n < kPoresPerCell; ++n) {
        uint h = mixHash(column + uint(n) * 0x9e3779b9u);
        float cx = (float(i) + unitOf(mixHash(h ^ 0x85ebca6bu))) * cell;
        float cy = (float(j) + unitOf(mixHash(h ^ 0xc2b2ae35u))) * cell;
        float dx = c.x - cx;
        float dy = c.y - cy;
        float d2 = dx * dx + dy * dy;
        if (d2 >= cell * cell) continue;
        float len = P.poreLength * (0.5f + unitOf(mixHash(h ^ 0x27d4eb2fu)));
        float stagger = unitOf(mixHash(h ^ 0x165667b1u)) * len;
        int k = int(floor((c.height + stagger) / len));
        uint segment = hash3(i * kPoresPerCell + n, j, k, u_hashSeed + kPoreCell);
        if (unitOf(segment) >= density / float(kPoresPerCell)) continue;  // on average `density` pores a cell
        float r = min(radius * (0.7f + 0.6f * unitOf(mixHash(segment ^ 0x9e3779b9u))), cell);
        float halfLength = 0.5f * len * (0.6f + 0.35f * unitOf(mixHash(segment ^ 0xc2b2ae35u)));
        float dh = (c.height - ((float(k) + 0.5f) * len - stagger)) / halfLength;
        weight = max(weight, holeProfile(d2 / (r * r) + dh * dh));
      }
    }
  }
  return weight;
}

float rayWeight(Cylindrical c) {
  if (P.rayDensity <= 0.0f || P.rayOpacity <= 0.0f) return 0.0f;
  // Rays run radially: stratified in angle and height (Liu Sec. 4.6), in radial bands of one ray length.
  float bandLength = P.rayLength;
  int band = int(floor(c.radius / bandLength));
  float bandMiddle = (float(band) + 0.5f) * bandLength;
  int count = max(1, int(round(2.0f * kPi * bandMiddle / P.raySpacing)));
  float sector = 2.0f * kPi / float(count);
  int i = min(int((c.azimuth + kPi) / sector), count - 1);
  float cellHeight = 3.0f * P.rayHeight;
  float stagger = unitOf(hash2(band, i, u_hashSeed + kRayColumn)) * cellHeight;
  int k = int(floor((c.height + stagger) / cellHeight));
  uint h = hash3(band, i, k, u_hashSeed + kRayCell);
  if (unitOf(h) >= P.rayDensity) return 0.0f;
  float centerAngle = -kPi + (float(i) + 0.5f + 0.45f * signedUnitOf(mixHash(h ^ 0x9e3779b9u))) * sector;
  float dAngle = c.azimuth - centerAngle;
  dAngle -= 2.0f * kPi * round(dAngle / (2.0f * kPi));
  float centerHeight = (float(k) + 0.5f + 0.15f * signedUnitOf(mixHash(h ^ 0x85ebca6bu))) * cellHeight - stagger;
  float dt = c.radius * dAngle / P.rayWidth;
  float dh = (c.height - centerHeight) / P.rayHeight;
  float q = c.radius / bandLength - float(band);  // taper: rays begin and end inside their band
  float taper = stepSmooth(0.0f, 0.12f, q) * (1.0f - stepSmooth(0.88f, 1.0f, q));
  return wyvill(dt * dt + dh * dh) * taper;
}

// Only the growth time at the (distorted) point: WoodSample.year without the texture's cost.
float woodYear(vec3 p) {
  vec3 unusedFiber;
  vec3 u = undistort(p, cylindricalOf(p, false), false, unusedFiber);
  Cylindrical c = cylindricalOf(u, true);
  float darkness;
  float shade;
  return mergeKnots(u, growthAt(c), c.radius, darkness, shade);
}

// The tree's frame in its growth layers: the cross-section radius replaced by the growth field's own,
// G x growth.ring_width, the azimuth and the height kept. In Liu et al. 2016 (Sec. 4.1) the rings are
// concentric cylinders in the undistorted frame, where the vessels, rays and fibres are placed, so they lie
// in the rings; the fitted growth rates (Mokume Sec. 5.2.2) bend the rings after that frame, so pores
// placed by the geometric radius ran straight through a ring that tilts or undulates. With this radius a
// vessel keeps its growth time along the grain: where the rings undulate, the vessels follow them (on
// CN03's flat-sawn faces, long streaks hanging from the ring lines, as in the photos; docs/texture.md).
// With uniform rates G x ring_width is the radius itself.
Cylindrical inGrowthLayers(Cylindrical c, float stemYear) {
  float grown = max(stemYear * P.ringWidth, 0.0f);
  float scale = c.radius > 1e-6f ? grown / c.radius : 1.0f;
  c.x *= scale;
  c.y *= scale;
  c.radius = grown;
  return c;
}

// Where a point lies in the tree: what the growth field, its distortion and the knots decide, and no
// texture parameter (pores, rays, fibres, colours) changes. The texture search computes it once per
// point and shades it for every candidate (texture/face_crops.hpp).
struct WoodLocation {
  Cylindrical c;        // the undistorted point in the tree's frame, in its growth layers (inGrowthLayers)
  float year;           // WoodSample.year
  float knotDarkness;   // how much a knot darkens the point (Larsson et al. 2022 Sec. 4.3)
  float knotShade;      // a dead knot's bark ring: its colour factor (Sec. 4.3); 1 elsewhere
  vec3 fiberDirection;  // WoodSample.fiberDirection
};

WoodLocation locateWood(vec3 p, bool wantFiber) {
  WoodLocation w;
  Cylindrical distorted = cylindricalOf(p, false);  // undistort needs no azimuth
  vec3 u = undistort(p, distorted, wantFiber, w.fiberDirection);
  Cylindrical c = cylindricalOf(u, true);
  float stemYear = growthAt(c);
  w.year = mergeKnots(u, stemYear, c.radius, w.knotDarkness, w.knotShade);  // Mokume Sec. 5.2.4 Eq. 7
  w.c = inGrowthLayers(c, stemYear);
  return w;
}

// The wood at a located point in two steps: the layers, each set by its own group of texture parameters,
// and their composition into the colour. The texture search (texture/shading_layers.hpp) computes a layer
// once for all candidates that agree on its parameters: a candidate that changes only the rays keeps the
// pores, fibres and rings of the others.
struct WoodLayers {
  float latewood;     // seasonOf(year): rings.offset, latewood_fraction, transition, boundary_softness
  float pore;         // poreWeight: pores.* but darkness and shadow hue, and the rings' season
  float ray;          // rayWeight: rays.* but colour; 0 where rays.density or rays.opacity is 0
  float fiber;        // fiberNoiseAt: fibers.width, fibers.length; 0 where fibers.strength is 0
  float ringProfile;  // ringProfileAt(year): rings.offset, rings.profile_*
  float ringNoise;    // the 1D ring colour noise at the year
  float mottle;       // the mottling noise: color.mottle_scale; 0 where color.mottle_strength is 0
};

float fiberLayer(Cylindrical c) {
  return P.fiberStrength > 0.0f ? fiberNoiseAt(c) : 0.0f;
}
float ringNoiseAt(float year) {
  return valueNoise1(year, u_hashSeed + kRingColor);
}
float mottleAt(Cylindrical c) {
  if (P.mottleStrength <= 0.0f) return 0.0f;
  float m = P.mottleScale;
  return fractalNoise3(vec3(c.x / m, c.y / m, c.height / (4.0f * m)), u_hashSeed + kMottle).x;
}

WoodLayers woodLayers(WoodLocation w) {
  WoodLayers l;
  l.latewood = seasonOf(w.year);
  l.pore = poreWeight(w.c, w.year);
  l.ray = rayWeight(w.c);
  l.fiber = fiberLayer(w.c);
  l.ringProfile = ringProfileAt(w.year);
  l.ringNoise = ringNoiseAt(w.year);
  l.mottle = mottleAt(w.c);
  return l;
}

// faceIndex 0..5 (A..F) applies that face's tint; -1 (cuts, volumes) none.
WoodSample composeWood(WoodLocation w, WoodLayers l, int faceIndex) {
  WoodSample s;
  float knotDarkness = w.knotDarkness;
  s.fiberDirection = w.fiberDirection;
  s.year = w.year;
  s.latewood = l.latewood;
  s.pore = l.pore;
  s.ray = l.ray;

  // Pigment concentration t (Beer's law, Liu Sec. 4.3-4.4).
  float t = P.seasonShading * s.latewood + l.ringProfile;
  t += 0.5f * P.ringColorVariation * l.ringNoise;
  if (P.mottleStrength > 0.0f) t += 0.5f * P.mottleStrength * l.mottle;
  s.pigment = t;
  s.shade = poreShadeOf(s.pore) * fiberShadeOf(l.fiber);

  float sap = stepSmooth(P.sapwoodStart - 0.5f * P.sapwoodTransition, P.sapwoodStart + 0.5f * P.sapwoodTransition, s.year);
  vec3 early = max(mix(P.earlywoodColor, P.sapwoodEarlywoodColor, sap), vec3(1e-3f));
  vec3 late = max(mix(P.latewoodColor, P.sapwoodLatewoodColor, sap), vec3(1e-3f));
  vec3 color = early * pow(late / early, vec3(t)) * s.shade;
  color = mix(color, P.rayColor, P.rayOpacity * s.ray);
  color -= knotDarkness * P.knotDarkening;  // Larsson et al. 2022 Sec. 4.3
  color *= w.knotShade;
  if (faceIndex == 0) color *= P.faceTintA;
  else if (faceIndex == 1) color *= P.faceTintB;
  else if (faceIndex == 2) color *= P.faceTintC;
  else if (faceIndex == 3) color *= P.faceTintD;
  else if (faceIndex == 4) color *= P.faceTintE;
  else if (faceIndex == 5) color *= P.faceTintF;
  s.color = clamp(color, 0.0f, 1.0f);
  return s;
}

// The wood at a located point. faceIndex 0..5 (A..F) applies that face's tint; -1 (cuts, volumes) none.
WoodSample shadeWood(WoodLocation w, int faceIndex) {
  return composeWood(w, woodLayers(w), faceIndex);
}

// faceIndex 0..5 (A..F) applies that face's tint; -1 (cuts, volumes) applies none.
WoodSample evaluateWood(vec3 p, int faceIndex, bool wantFiber) {
  return shadeWood(locateWood(p, wantFiber), faceIndex);
}
