#pragma once
// Knots in a block's growth field, Mokume Sec. 5.2.4 Eq. 7:
//   G_k(p) = smooth_min(G(p), G(omega_k, p), s)
// G is the block's growth field (years, field/growth_field.hpp). The knot's own growth field is, as in
// the authors' code (MOKUME_CONVENTIONS.md B.2, "knot"), a scaled distance from the knot axis:
//   T_k(p) = d_k(p) / (v_k w)
// d_k the distance from the knot's axis, a half-line from where the branch leaves the pith; v_k the
// knot's growth speed as a fraction of the stem's (the authors' 1 / knot_density; Larsson et al. 2022
// Sec. 4.1) and w the ring width (growth.ring_width). So a knot ring is v_k stem rings wide, and the
// knot itself (T_k < G) is a cone whose radius grows as v_k times the distance from the pith.
//
// The smooth minimum is Larsson et al. 2022's power smooth minimum (Eq. 2) with Mokume's single
// smoothness s = knots.k_stem (no adaptive k: see knotTerm), each knot's smoothing faded out by the
// window of knots.reach_start / reach_end on d_k / d_s (d_s the distance from the pith axis), and
// many knots merged as in Eq. 6: t = min(G, T_1..T_n) + sum_i window_i (smin_i - min_i). Beyond
// reach_end a knot is skipped, so there G_k equals G bit for bit. The knot is darkened by
// knots.darkening (Sec. 4.3). Mokume models only alive knots with straight axes (Sec. 7); Kerf adds
// dead knots (issue 19): from BlockKnot::deathTime on, Larsson et al. 2022 Sec. 4.2.2 Eq. 5 and Sec. 4.3
// as the log applies them (field/knot_field.hpp applyKnotDeath, deadKnotShade, inDeadKnotOutline), in
// stem time = G w / knots.stem_radius. The knot stops thickening, the stem's rings are no longer
// continuous with it (it is encased: G_k jumps at its surface), the sweep inverts (the butterfly), and it
// gets the dead darkening and the dark bark ring (no outline noise: a block knot has no noise tables).
// Every knot gets its checks (knots.checks, Kerf's own: model/kernels/knot_checks.glsl), as the log's do.
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "field/knot_field.hpp"

namespace kerf {

struct BlockKnot {
  int id = 0;                    // the knot id of its marks (rings/annotations.hpp KnotMark::knot)
  glm::vec3 origin{0.0f};        // block mm: where the knot axis starts (at the pith)
  glm::vec3 direction{1, 0, 0};  // unit, from the pith outward
  float speed = 0.16f;           // v_k: knot growth speed as a fraction of the stem's (knots.speed)
  // Issue 19 item 2: a branch thickens ever more slowly as the stem grows (Larsson et al. 2022 Sec. 4.1:
  // the knot speed declines with the stem time), so its diameter along its axis is no straight cone:
  //   v_k(G) = speed (G / taperAge)^-taper   (knotSpeedAt); 0 = Mokume's cone from the pith.
  // Fitted where the knot's edge is seen on two faces (fit/block_knot_fit.hpp); taper near 1 is a knot
  // that stopped thickening, as a dead one does.
  float taper = 0.0f;
  float taperAge = 10.0f;  // the stem time G (years from the pith) at which v_k = speed
  // The stem time G (years from the pith) at which the branch died; infinity: alive. After it the knot
  // keeps the section it had (its speed and taper are those of its death) and is encased (Eq. 5).
  float deathTime = std::numeric_limits<float>::infinity();

  bool dead() const { return std::isfinite(deathTime); }

  bool operator==(const BlockKnot&) const = default;
};

inline constexpr float kMaxKnotTaper = 0.95f;  // below 1: the knot still starts on the pith with no width

// v_k at stem time G (BlockKnot::taper), for any scalar type (Ceres Jets in the fit); capped at
// maxSpeed, since past the reach a knot could not be the minimum (knotTerm).
// The fit calls taperedKnotSpeed itself: at taper 0 its Jets keep the derivative in the taper.
template <typename T>
T taperedKnotSpeed(const T& speed, const T& taper, float taperAge, const T& stemTime, float maxSpeed) {
  using std::pow;
  const T age = stemTime > T(1e-3f) ? stemTime : T(1e-3f);
  const T v = speed * pow(age / T(taperAge), -taper);
  return v < T(maxSpeed) ? v : T(maxSpeed);
}
template <typename T>
T knotSpeedAt(const T& speed, const T& taper, float taperAge, const T& stemTime, float maxSpeed) {
  if (!(taper != T(0))) return speed;  // bit for bit the cone of Eq. 7
  return taperedKnotSpeed(speed, taper, taperAge, stemTime, maxSpeed);
}
// The cap knotTerm's window needs: 0.9 x the nearer reach (the log's cap, field/knot_field.hpp).
inline float maxKnotSpeed(const KnotSettings& s) {
  return 0.9f * std::min(s.knotReachStart, s.knotReachEnd);
}

// The most knots a block may hold (issue 21): every knot is evaluated at every pixel and sample of the
// block (no culling), so the work of a render grows with pixels x knots. A block has a handful of knots.
inline constexpr std::size_t kMaxBlockKnots = 1'000;

// Throws InputError naming `what` (e.g. "knots[1]") for a non-finite or zero direction, a speed outside
// (0, 1), a taper outside [-kMaxKnotTaper, kMaxKnotTaper], a taper age that is not positive or a death
// time that is not positive (infinity: alive).
void validate(const BlockKnot& knot, const std::string& what);

// The distance from p to the knot's half-line, for any scalar type (Ceres Jets in the fit).
template <typename T>
T knotAxisDistance(const T* origin, const T* unitDirection, const glm::vec3& p) {
  using std::sqrt;
  const T rel[3] = {T(p.x) - origin[0], T(p.y) - origin[1], T(p.z) - origin[2]};
  T along = rel[0] * unitDirection[0] + rel[1] * unitDirection[1] + rel[2] * unitDirection[2];
  if (along < T(0)) along = T(0);
  const T d[3] = {rel[0] - along * unitDirection[0], rel[1] - along * unitDirection[1],
                  rel[2] - along * unitDirection[2]};
  return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// How far a mark on a face lies from the knot's axis, measured where the user placed it: on the face's
// plane, from the mark to where the axis line meets that plane (issue 19 item 1: a mark's accuracy is a
// distance on the photo). Across the axis (knotAxisDistance) it is shorter by the cosine of the axis's
// angle to the face normal: 0.75 at 41 deg, so a 1 mm accuracy held that way let the axis cross the face
// 1.2 mm from the mark (the steep block of the spruce log bed, docs/knots.md). An axis within ~6 deg of
// the face's plane meets it far away or never; there the plane distance is taken at that angle. Never less
// than knotAxisDistance (which the plane distance always is at least for a mark beyond the knot's start).
template <typename T>
T knotAxisMarkDistance(const T* origin, const T* unitDirection, const glm::vec3& mark,
                       const glm::vec3& normal) {
  using std::sqrt;
  const T rel[3] = {T(mark.x) - origin[0], T(mark.y) - origin[1], T(mark.z) - origin[2]};
  T dn = unitDirection[0] * T(normal.x) + unitDirection[1] * T(normal.y) + unitDirection[2] * T(normal.z);
  const T minCos(0.1);
  if (dn >= T(0) && dn < minCos) dn = minCos;
  if (dn < T(0) && dn > -minCos) dn = -minCos;
  const T t = (rel[0] * T(normal.x) + rel[1] * T(normal.y) + rel[2] * T(normal.z)) / dn;
  const T d[3] = {t * unitDirection[0] - rel[0], t * unitDirection[1] - rel[1],
                  t * unitDirection[2] - rel[2]};
  // Within the plane: the part of d along the normal is what the clamp above left over; drop it.
  const T dNormal = d[0] * T(normal.x) + d[1] * T(normal.y) + d[2] * T(normal.z);
  const T e[3] = {d[0] - dNormal * T(normal.x), d[1] - dNormal * T(normal.y), d[2] - dNormal * T(normal.z)};
  const T inPlane = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + T(1e-12));
  const T across = knotAxisDistance(origin, unitDirection, mark);
  return inPlane > across ? inPlane : across;
}

// One knot's term of Eq. 6 at a point: its time T_k and its windowed smoothing (<= 0). The window is
// 0 (and the knot is to be skipped) where d_k >= reach_end d_s.
template <typename T>
struct KnotTerm {
  T time;
  T smoothing;
  T window;
};
// The knot's dead-knot state at a point (BlockKnot::deathTime): the death time and the angle beta around
// the knot axis (0 = sideways, pi/2 = towards the pith axis' direction, Larsson's "above"). An alive
// knot has deathTime = infinity and beta is not used.
template <typename T>
struct KnotDeathAt {
  T deathTime;
  T beta;
};
// Years to Larsson's stem time (0 at the pith, 1 at the bark): G w / knots.stem_radius.
inline float stemTimePerYear(float ringWidth, const KnotSettings& s) {
  return ringWidth / s.knotStemRadius;
}

template <typename T>
KnotTerm<T> knotTerm(const T& stemTime, const T& knotDistance, const T& stemRadius, const T& speed,
                     float ringWidth, const T& kStem, const KnotSettings& s,
                     const KnotDeathAt<T>& death = {T(std::numeric_limits<float>::infinity()), T(0)}) {
  KnotTerm<T> out{T(0), T(0), T(0)};
  if (!(stemRadius > T(1e-3f))) return out;
  out.window = knotWindowOf(knotDistance / stemRadius, s.knotReachStart, s.knotReachEnd);
  if (!(out.window > T(0))) return out;
  out.time = knotDistance / (speed * T(ringWidth));
  // One smoothness s for the whole union, as Mokume's Eq. 7 (knots.k_stem), not Larsson's adaptive k:
  // where k switches from k_knot to k_stem at the knot's edge, G_k falls by up to 0.13 years moving
  // outward (measured with the schema defaults), and rings would fold there.
  const T m = out.time < stemTime ? out.time : stemTime;
  const T alive = powerSmoothMinOf(stemTime, out.time, kStem);
  T delta = alive - m;  // Eq. 2-3
  if (death.deathTime < stemTime) {
    // Eq. 5 in Larsson's stem time (the log's code), and back to years. Where the log tests its union
    // (adaptive k, near k_knot = 5 inside a knot: almost the minimum) against the death, the block tests the
    // minimum itself: with its one soft k (fitted near 1) the union would let a dead knot thicken on by a
    // third. So the knot's section stays exactly that of its death, and G_k is continuous outside it.
    const float c = stemTimePerYear(ringWidth, s);
    T knotTime = out.time * T(c);
    T deadDelta = delta * T(c);
    if (applyKnotDeath(stemTime * T(c), m * T(c), death.deathTime * T(c), kStem, death.beta, s, knotTime,
                       deadDelta)) {
      out.time = knotTime / T(c);
      delta = deadDelta / T(c);
    }
  }
  out.smoothing = out.window * delta;
  return out;
}

struct BlockKnotSample {
  float time = 0;      // G_k (years)
  float darkness = 0;  // the share of knots.darkening to subtract (Sec. 4.3): 0..1, plus a dead knot's shade
  float shade = 1;  // colour factor: knots.outline_shade inside a dead knot's bark ring (Sec. 4.3), else 1,
                    // times the knot checks' (knots.checks, model/kernels/knot_checks.glsl)
  int knotsInReach = 0;
};

// The angle around the knot's axis of the point `rel` (from the knot's origin), 0 beside it, pi/2 along
// `up` (the pith axis made perpendicular to the knot): Larsson's beta (Sec. 4.2.2), for the butterfly.
template <typename T>
T knotAngleOf(const T* rel, const T* unitDirection, const glm::vec3& up, const glm::vec3& side) {
  using std::atan2;
  const T along = rel[0] * unitDirection[0] + rel[1] * unitDirection[1] + rel[2] * unitDirection[2];
  T r[3];
  for (int i = 0; i < 3; ++i) r[i] = rel[i] - along * unitDirection[i];
  return atan2(r[0] * T(up.x) + r[1] * T(up.y) + r[2] * T(up.z),
               r[0] * T(side.x) + r[1] * T(side.y) + r[2] * T(side.z));
}
// `up` and `side` of a knot direction and the pith axis direction (both unit).
void knotFrame(const glm::vec3& direction, const glm::vec3& pithDirection, glm::vec3& up, glm::vec3& side);

// The knots of one block with the settings they are merged with. Immutable and thread-safe.
class BlockKnots {
 public:
  BlockKnots() = default;
  // pithDirection: the growth field's pith axis (unit), "up" for the butterfly of dead knots.
  BlockKnots(std::vector<BlockKnot> knots, const KnotSettings& settings, float ringWidthMm,
             glm::vec3 pithDirection = glm::vec3(0, 0, 1));

  bool empty() const { return knots_.empty(); }
  const std::vector<BlockKnot>& knots() const { return knots_; }
  const KnotSettings& settings() const { return settings_; }
  float ringWidth() const { return ringWidth_; }
  // Per knot, its frame for beta (knotAngleOf): what the shaders get as uniforms.
  const glm::vec3& up(std::size_t knot) const { return up_[knot]; }
  const glm::vec3& side(std::size_t knot) const { return side_[knot]; }

  // G_k at p (block mm) from the stem time G(p) and the distance of p from the pith axis (mm).
  BlockKnotSample merge(const glm::vec3& p, float stemTime, float stemRadius) const;

 private:
  std::vector<BlockKnot> knots_;
  std::vector<glm::vec3> up_, side_;
  KnotSettings settings_;
  float ringWidth_ = 1.0f;
};

}  // namespace kerf
