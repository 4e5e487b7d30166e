// Dead knots, Larsson et al. 2022 Sec. 4.2.2 (Eq. 5) and Sec. 4.3, shared by the log's knots
// (knots.glsl) and the block's (wood_model.glsl): the GLSL twin of deadKnotFactorOf, applyKnotDeath,
// inDeadKnotOutline and deadKnotShade in core/field/knot_field.hpp, same float operations in the same
// order. All times are Larsson's stem time (0 at the pith, 1 at the bark). Needs the schema's P.

// Eq. 2 (powerSmoothMinOf).
float knotSmoothMinOf(float a, float b, float k) {
  float m = b < a ? b : a, M = a < b ? b : a;
  if (!(m > 0.0)) return max(m, 0.0);
  return m * pow(1.0 + pow(m / M, k), -1.0 / k);
}

// Sec. 4.2.2 (deadKnotFactorOf).
float knotDeadFactor(float tau, float beta) {
  float wing = 1.0 - P.knotButterfly * cos(2.0 * beta);
  float progress = 1.0 - exp(-P.knotDeadTransition * (tau > 0.0 ? tau : 0.0));
  return 1.0 + (P.knotDeadInversion * wing - 1.0) * progress;
}

// Eq. 5 (applyKnotDeath): past the death the knot stops thickening, sharpens and inverts its fillet.
bool applyKnotDeath(float ts, float tAlive, float tDeath, float k, float beta, inout float knotTime,
                    inout float delta) {
  if (!(tAlive > tDeath)) return false;
  float tau = ts - tDeath;
  knotTime += tau;
  float m = knotTime < ts ? knotTime : ts;
  delta = knotDeadFactor(tau, beta) * (knotSmoothMinOf(ts, knotTime, k + P.knotDeadSharpening * tau) - m);
  return true;
}

// Sec. 4.3 (inDeadKnotOutline): the bark ring where the knot's surface froze.
bool inDeadKnotOutline(float ts, float tb, float tDeath, float width) {
  return ts > tDeath && abs(tb - tDeath) < width;
}

// Sec. 4.3 (deadKnotShade): dead knot wood grown after the death is darker.
float deadKnotShade(float ts, float tb, float tDeath) {
  if (!(ts > tDeath && tb < ts)) return 0.0;
  return min(1.0, 3.0 * (ts - tDeath)) * P.knotDeadDarkening;
}
