// Checks: the radial drying cracks of a knot, as a cut through it shows them (issue 19 item 4). Single
// source for the core (model/knot_check_kernels.hpp: the log's KnotField, the block's BlockKnots) and the
// shaders (shaders/knots.glsl, shaders/wood_model.glsl); needs kernels/noise.glsl (mixHash, hash1,
// unitOf, valueNoise1).
//
// Kerf's own addition: Larsson et al. 2022 model no cracks; they name cracks among the features still to
// add (Sec. 7, "cracks, rays, pores, fiber directions") and splits as open work (Sec. 1). What a
// woodworker sees: branch wood shrinks more around its rings than along its radius as it dries, so a knot
// splits along a few planes through its own axis. On a cut across the knot they are thin dark cracks
// running out from near the knot's pith, closed at their inner tip and widest towards the knot's edge;
// many and open in dead (loose, bark-encased) knots, one or two faint ones in large live knots, none in
// small live ones.
//
// Per knot (a hash of its id, so the same on every cut, CPU and GPU): 3-5 crack planes at jittered
// angles around the knot's axis (one per sector of the circle, irregularly placed in it). Each runs from
// 0.05-0.25 of the knot's radius to 0.85-1.25 of it (past 1: through to the bark ring), opens and closes
// along the branch (1D value noise over the distance along it, 12 mm lattice), turns slowly along it and
// wanders a little across it (a gentle bend of 2 % of the knot's radius and a 0.06 mm jag). Its open
// half-width, 0.045 sqrt(radius in mm) mm at most at strength 1, tapers from 0 at the inner tip to its
// widest at 0.7 of its length, then closes at its outer tip.
//
// Arguments: knot, the knot's id; distance, from the knot's axis (mm); radius, the knot's radius there
// (mm: its section at this point, frozen at its death); beta, the angle around the knot's axis; along,
// the distance along the knot (mm); stemTime, deathTime in Larsson's stem time (deathTime past stemTime:
// alive here); strength, knots.checks (0 = none). Returns the colour factor: 1 = no crack, down to 0.3 in
// the middle of an open one.

KERF_CONST int kKnotCheckSlots = 5;
KERF_CONST float kKnotCheckTwoPi = 6.28318530717959f;
KERF_CONST float kKnotCheckFeather = 0.04f;  // mm: the soft edge of a crack (a crack's shadowed lip)

float knotCheckShade(int knot, float distance, float radius, float beta, float along, float stemTime,
                     float deathTime, float strength) {
  if (!(strength > 0.0f) || !(radius > 0.0f)) return 1.0f;
  float rho = distance / radius;
  if (!(rho < 1.0f)) return 1.0f;
  // Dead knot wood (after the death, ramping over 0.1 of stem time) gets every crack at full width; live
  // wood only the first two, faint (0.35) and fading out below a knot radius of 3-10 mm.
  float deadness = stemTime > deathTime ? clamp(10.0f * (stemTime - deathTime), 0.0f, 1.0f) : 0.0f;
  float size = clamp((radius - 3.0f) / 7.0f, 0.0f, 1.0f);
  float live = 0.35f * size * size * (3.0f - 2.0f * size);
  uint seed = mixHash(uint(knot) * 0x9e3779b9u + 0x632be5abu);
  int count = 3 + int(unitOf(seed) * 3.0f);
  float start = kKnotCheckTwoPi * unitOf(hash1(-1, seed));
  float shade = 1.0f;
  for (int i = 0; i < kKnotCheckSlots; ++i) {
    if (i >= count) break;
    float weight = i < 2 ? live + (1.0f - live) * deadness : deadness;
    if (!(weight > 0.0f)) continue;
    uint h = hash1(i, seed);
    float inner = 0.05f + 0.2f * unitOf(hash1(1, h));
    float outer = 0.85f + 0.4f * unitOf(hash1(2, h));
    if (!(rho > inner) || !(rho < outer)) continue;
    float open = clamp(0.55f + 1.1f * valueNoise1(along * (1.0f / 12.0f) + 17.0f * float(i), h), 0.0f, 1.0f);
    if (!(open > 0.0f)) continue;
    float angle = start + kKnotCheckTwoPi * (float(i) + 0.2f + 0.6f * unitOf(hash1(3, h))) / float(count) +
                  0.15f * valueNoise1(along * (1.0f / 25.0f), h ^ 0x5bd1e995u);
    float d = beta - angle;
    d -= kKnotCheckTwoPi * floor(d * (1.0f / kKnotCheckTwoPi) + 0.5f);
    if (!(abs(d) < 1.0f)) continue;
    float wander = 0.02f * radius * valueNoise1(rho * 3.0f + 31.0f * float(i), h ^ 0x68bc21ebu) +
                   0.06f * valueNoise1(distance * (1.0f / 0.7f) + 57.0f * float(i), h ^ 0x2c1b3c6du);
    float lateral = abs(distance * sin(d) - wander);
    float s = (rho - inner) / (outer - inner);
    float s2 = s * s;
    float s4 = s2 * s2;
    float profile = sqrt(s) * (1.0f - s4 * s4) * (1.0f / 0.79f);
    float halfWidth = strength * weight * open * profile * (0.6f + 0.4f * unitOf(hash1(4, h))) * 0.045f *
                      sqrt(radius);
    float cover = clamp((halfWidth - lateral) / kKnotCheckFeather + 0.5f, 0.0f, 1.0f) *
                  clamp(halfWidth / kKnotCheckFeather, 0.0f, 1.0f);
    shade = min(shade, 1.0f - 0.7f * cover);
  }
  return shade;
}
