#pragma once
// A tree log as the knot model of Larsson et al. 2022 (shared/papers/larsson-procedural-knots-2022.txt)
// sees it: the stem (pith curve and outer radius by height and azimuth, the "stem map" of Sec. 4.4.1,
// Table 1) and its knots (per knot, as functions of the distance d from the pith: height, azimuth around
// the stem, alive/dead, the knot maps of Sec. 4.4.2, Table 2). See docs/knots.md.
//
// Log frame, millimetres: z runs up the log from its lowest slice (z = 0); x, y are horizontal with the
// pith of the middle slice at (0, 0). Azimuths are radians around the pith, from +x towards +y.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

namespace kerf {

// The stem: pith position and outer (bark-side) radius on a regular grid of heights x azimuths.
struct Stem {
  float heightStep = 10.0f;     // mm between slices; slice i lies at z = i * heightStep
  int azimuths = 360;           // radius samples per slice, evenly around the full circle
  std::vector<glm::vec2> pith;  // one per slice
  std::vector<float> radii;     // slices x azimuths, row-major, mm

  int slices() const { return static_cast<int>(pith.size()); }
  float height() const { return heightStep * static_cast<float>(slices() > 0 ? slices() - 1 : 0); }
  // Pith position at height z (linear between slices, clamped at the ends).
  glm::vec2 pithAt(float z) const;
  // Outer radius at height z and azimuth (radians): bilinear, periodic in azimuth, clamped in z.
  float radiusAt(float z, float azimuth) const;
  float minRadius() const;
  float maxRadius() const;
  // Bounding box of the pith's x, y over heights [z0, z1] (exact for the piecewise-linear curve).
  void pithRange(float z0, float z1, glm::vec2& lo, glm::vec2& hi) const;
};

// One knot: its skeleton as sampled functions of the distance d from the pith (Table 2): the height z(d)
// and azimuth omega(d) of the branch's centre line, and when it died.
struct Knot {
  float distanceStep = 4.0f;    // mm between samples; sample j lies at d = j * distanceStep
  std::vector<float> heights;   // z(d_j), mm
  std::vector<float> azimuths;  // omega(d_j), radians, unwrapped (no jumps of 2 pi)
  float deathDistance = std::numeric_limits<float>::infinity();  // alive for d < this; inf = never died
  float endDistance =
      std::numeric_limits<float>::infinity();  // where the branch broke off (kept, not rendered)

  int samples() const { return static_cast<int>(heights.size()); }
  float maxDistance() const { return distanceStep * static_cast<float>(samples() - 1); }
  bool aliveAt(float d) const { return d < deathDistance; }
  // Linear in d, clamped at the ends (the branch continues straight beyond its last sample).
  float heightAt(float d) const;
  float azimuthAt(float d) const;
  // Ranges of z(d) and omega(d) over d in [d0, d1] (exact for the piecewise-linear tables).
  void heightRange(float d0, float d1, float& lo, float& hi) const;
  void azimuthRange(float d0, float d1, float& lo, float& hi) const;
};

// A sampled 1D wood colour map from pith (t = 0) to bark (t = 1) (Sec. 4.3).
struct WoodColorMap {
  std::vector<glm::vec3> colors;  // sRGB 0..1, evenly over t in [0, 1]
  bool empty() const { return colors.empty(); }
  glm::vec3 at(float t) const;  // linear, clamped
};

struct LogModel {
  std::string name;
  Stem stem;
  std::vector<Knot> knots;
  WoodColorMap colorMap;  // empty: none came with the log (the renderer builds one from the parameters)
};

// Checks sizes, finiteness and that every knot starts inside the stem; throws InputError naming the knot.
void validate(const LogModel& log);

// A stem radius sample this many times above or below the log's median radius is not a measurement but a
// mistake (issue 21: one CT sample of 1e30 mm changed the whole board through the log's largest radius).
// Real stems vary far less: Gran_1's 144,000 CT radii lie within 0.85-1.17 of their median.
inline constexpr float kPlausibleRadiusFactor = 4.0f;
// Throws InputError naming `where`, the slice and azimuth, the value and the median unless every sample
// of `radii` (slices x `azimuths`, row-major, positive) lies within kPlausibleRadiusFactor of the median.
void checkPlausibleRadii(const std::vector<float>& radii, int azimuths, const std::string& where);

// The most knots a log may hold (issue 21: a 10 MB log of 100k knots needed 3.4 GB). Each knot keeps two
// 64 x 64 noise tables (32 KiB, field/knot_field.hpp) and is culled at every pixel it may reach; the
// Gran_1 spruce log has 108 knots. 10000 knots take 320 MiB of tables.
inline constexpr std::size_t kMaxLogKnots = 10'000;
// Throws InputError naming `where` (the file) unless `count` knots are within kMaxLogKnots. The readers
// call it before they build a knot; validate(log) again for logs made otherwise.
void checkLogKnotCount(std::size_t count, const std::string& where);

// A plausible random spruce-like log (deterministic for a seed): a gently curved pith, a tapering
// slightly out-of-round stem, knots in whorls every `whorlSpacing` mm with branches rising and twisting a
// little, knots dying (alive-to-dead transition) at a random distance that is smaller low in the log.
struct RandomLogOptions {
  std::uint32_t seed = 1;
  float lengthMm = 1500.0f;
  float radiusMm = 120.0f;
  float whorlSpacingMm = 350.0f;
  int knotsPerWhorl = 4;
};
LogModel generateRandomLog(const RandomLogOptions& options);

// The height window of the given length holding the most knots at `distanceMm` from the pith (0: where
// they start), a knotty section; returns its centre. The middle of the log when there are no knots.
float knottiestHeight(const LogModel& log, float windowMm, float distanceMm = 0.0f);

}  // namespace kerf
